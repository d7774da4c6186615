#include "scene/mesh_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>

#include "util/error.h"
#include "util/number_text.h"

namespace mb {

TriangleMesh load_mesh(const std::string& file) {
  if (!std::filesystem::exists(file)) throw InputError(file + ": mesh file not found");
  if (std::filesystem::is_directory(file))
    throw InputError(file + ": is a directory, expected a mesh file");
  Assimp::Importer importer;
  // Points and lines are dropped: only surfaces cast and receive shadows. PreTransformVertices
  // flattens the node hierarchy into world coordinates.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      file, aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode)
    throw InputError(file + ": cannot read mesh: " + importer.GetErrorString());
  TriangleMesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    if (!(part->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    uint32_t base = uint32_t(mesh.vertices.size());
    for (unsigned v = 0; v < part->mNumVertices; ++v) {
      const aiVector3D& p = part->mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw InputError(file + ": vertex " + std::to_string(v + 1) + " of mesh " +
                         std::to_string(m) + " is not finite (" + round_trip(p.x) + ", " +
                         round_trip(p.y) + ", " + round_trip(p.z) + ")");
      mesh.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.triangles.push_back(
          {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
  if (mesh.triangles.empty()) throw InputError(file + ": mesh has no triangles");
  return mesh;
}

}  // namespace mb
