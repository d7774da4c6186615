#include "scene/mesh_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

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
    // A face listed twice (either winding) is one surface: scanned meshes carry such repeats
    // (data/dragon.ply: 1 489), and a translucent surface counted twice would absorb twice
    // (docs/transparency.md §1). The first copy is kept.
    // Faces are compared by their corners' positions: some importers (OBJ) give every face its
    // own vertices.
    std::map<std::array<float, 3>, uint32_t> first_at;
    std::vector<uint32_t> position_id(part->mNumVertices);
    for (unsigned v = 0; v < part->mNumVertices; ++v) {
      const aiVector3D& q = part->mVertices[v];
      position_id[v] = first_at.try_emplace({q.x, q.y, q.z}, v).first->second;
    }
    std::set<std::array<uint32_t, 3>> seen;
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) continue;
      std::array<uint32_t, 3> key = {position_id[face.mIndices[0]], position_id[face.mIndices[1]],
                                     position_id[face.mIndices[2]]};
      std::sort(key.begin(), key.end());
      if (!seen.insert(key).second) continue;
      mesh.triangles.push_back(
          {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
  if (mesh.triangles.empty()) throw InputError(file + ": mesh has no triangles");
  return mesh;
}

}  // namespace mb
