#pragma once
// Every surface crossing every texel centre of one light view, sorted by depth (docs/reference.md
// §3: the depth-layer stack; layer 0 is the ordinary shadow map). Stored as CSR over texels.
#include <cstdint>
#include <string>
#include <vector>

namespace mb {

struct LayerStack {
  int width = 0, height = 0;
  // Texel t = row * width + column owns fragments [offsets[t], offsets[t + 1]).
  std::vector<uint64_t> offsets;
  std::vector<double> depth;       // in [0, 1], ascending within a texel
  std::vector<uint8_t> facing;     // 1 if the surface faces the light (a receiver, REFERENCE §3)
  std::vector<double> dz_dx;       // depth gradient of the fragment's triangle, per texel along x
  std::vector<double> dz_dy;       // ... along y (raster rows, downwards)
  std::vector<uint32_t> triangle;  // the fragment's triangle, when RasterInput::keep_triangles
  // Opacity of the fragment's surface (docs/reference.md §7); empty when every surface is opaque.
  // Float: what the deep EXR's A channel holds, so a stack read back is the same.
  std::vector<float> alpha;
  std::string scene, view, frame;  // provenance, written to the file header

  size_t texel_count() const { return size_t(width) * size_t(height); }
  size_t fragment_count() const { return depth.size(); }
  bool translucent() const { return !alpha.empty(); }
  int layers(size_t texel) const { return int(offsets[texel + 1] - offsets[texel]); }
  // The shadow map value: nearest surface, or the far plane 1 where the texel is empty.
  double layer0_depth(size_t texel) const { return layers(texel) ? depth[offsets[texel]] : 1.0; }
  bool same_fragments(const LayerStack& other) const;
};

struct LayerStackStats {
  size_t triangles = 0, fragments = 0, receivers = 0, covered_texels = 0;
  int max_layers = 0;
  double mean_layers = 0;  // over covered texels
};

LayerStackStats compute_stats(const LayerStack& stack, size_t triangles);

}  // namespace mb
