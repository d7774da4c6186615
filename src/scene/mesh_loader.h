#pragma once
// Mesh files through assimp (OBJ, PLY, OFF, STL, glTF, 3DS, ...), validated: a mesh with no
// triangles, or a NaN or infinite vertex, is an error naming the file and the vertex.
#include <string>

#include "scene/mesh.h"

namespace mb {

TriangleMesh load_mesh(const std::string& file);

}  // namespace mb
