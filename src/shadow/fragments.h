#pragma once
// The receivers of one light view and their PCF reference (docs/reference.md §3): every fragment of
// every layer that faces the light, each with its depth z_f, its own depth bias delta_f from its
// triangle plane, and the reference shadow intensity over layer 0.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "raster/layer_stack.h"
#include "shadow/gaussian_kernel.h"

namespace mb {

// What the techniques are compared against (docs/reference.md §3).
enum class Reference {
  // PCF = F_Z(z_f - delta_f), the paper's protocol: the same test every technique bounds, so an
  // exact technique's error is pure light leaking (what the moments do not know).
  Biased,
  // Each tap against the fragment's own plane, z_f + o . grad z_f - c (Bavoil, seed 001): the
  // ideal filtered hard shadow. Never lighter than F_Z(z_f - delta_f) when s >= 1.
  ReceiverPlane,
};
const char* reference_name(Reference reference);
// "biased" or "receiver_plane"; InputError naming `key` otherwise.
Reference parse_reference(const std::string& text, const std::string& key);

// One depth bias for the reference and every technique (docs/reference.md §3):
// delta_f = c + s * r * (|dz/dx| + |dz/dy|), r the kernel radius in texels. With s >= 1 the
// receiver's own plane lies behind z_f - delta_f at every tap, so it never shadows itself. s = 0
// with a constant c is the old constant bias (which lets sloped receivers shadow themselves).
struct BiasParams {
  Reference reference = Reference::Biased;
  double slope = 1;        // s
  double constant = 1e-4;  // c: absorbs curvature and rasterisation rounding
};
double fragment_bias(const BiasParams& bias, int kernel_radius, double dz_dx, double dz_dy);

// The ordinary shadow map: layer-0 depth per texel, 1 (the far plane) where the texel is empty.
// With translucent occluders (docs/reference.md §7) each texel also holds the distribution Z_t of
// where its light ray stops: atoms [atom_offsets[t], atom_offsets[t + 1]) with depth z_i and mass
// T(z_i) alpha_i, every surface up to the first opaque one, then the far plane with what is left.
// Atoms are indexed globally; atom_count() (one past the last) is the far plane outside the map.
// Without translucency the atoms are the texels: Z_t = delta at depth[t].
struct ShadowMap {
  int width = 0, height = 0;
  std::vector<double> depth;
  std::vector<uint64_t> atom_offsets;  // empty: every surface is opaque
  std::vector<double> atom_depth, atom_mass;
  // What the map's blending gives each atom when it is not the exact sorted blend (BlendOrder::
  // Submission); empty: atom_mass. The moment maps and the kernel's atoms read these, the reference
  // atom_mass.
  std::vector<double> atom_blend;
  // Submission only: each texel's atoms in the order its blend draws them, in the texel's own
  // range: the last atom (the opaque pass or the clear) first, then the translucent surfaces in
  // triangle order. Empty: back to front, the order that gives atom_mass (moment_map.cpp rounds
  // each step in this order for stored formats).
  std::vector<uint64_t> atom_draw;
  // Each atom's opacity alpha (1 for the first opaque surface, 0 for the far plane): what an
  // order-independent absorbance map (Fourier opacity mapping) accumulates.
  std::vector<double> atom_alpha;
  bool translucent() const { return !atom_offsets.empty(); }
  const std::vector<double>& blended_mass() const {
    return atom_blend.empty() ? atom_mass : atom_blend;
  }
  size_t atom_count() const { return translucent() ? atom_depth.size() : depth.size(); }
  // Depth at (x, y); outside the map counts as the far plane (docs/reference.md §3).
  double at(int x, int y) const {
    return x < 0 || y < 0 || x >= width || y >= height ? 1.0 : depth[size_t(y) * width + x];
  }
};
// How a translucent moment map blends its texels' surfaces (docs/reference.md §7): Sorted, front
// to back, gives the exact E_Z[b] (seed 004 asks for "any OIT method"); Submission blends them in
// the scene's triangle order over the first opaque surface, as an unsorted GPU pass does.
enum class BlendOrder { Sorted, Submission };
// The shadow map of a stack, with its texels' translucent distributions when any alpha < 1
// (Submission needs the stack's triangles).
ShadowMap layer0_shadow_map(const LayerStack& stack, BlendOrder order = BlendOrder::Sorted);

struct Fragments {
  int width = 0, height = 0;
  std::vector<uint32_t> texel;  // row * width + column
  std::vector<uint16_t> layer;  // 0 = the shadow map's own surface
  std::vector<double> zf;       // fragment depth
  std::vector<double> ztest;    // z_f - delta_f: the depth every technique is evaluated at
  std::vector<double> oracle;   // F_Z(z_f - delta_f); 0 means G = 0 exactly (docs/reference.md §2)
  std::vector<double> pcf;      // the reference shadow intensity in [0, 1] (= oracle if Biased)
  // Taps of the kernel with a surface in front of z_f - delta_f, of kernel_taps (ShadowRegion).
  std::vector<uint32_t> covered_taps;
  int kernel_taps = 0;
  size_t size() const { return zf.size(); }
};

// Where a receiver lies in the shadow (docs/reference.md §3): no tap of its kernel has a surface
// in front of z_f - delta_f (unshadowed: the reference is 0, and an exact technique too), every tap
// has one (interior: an umbra, or a translucent occluder's inside), or some do (silhouette: the
// kernel straddles an occluder's edge).
enum class ShadowRegion { Unshadowed, Silhouette, Interior };
inline ShadowRegion shadow_region(const Fragments& f, size_t k) {
  if (f.covered_taps[k] == 0) return ShadowRegion::Unshadowed;
  return int(f.covered_taps[k]) == f.kernel_taps ? ShadowRegion::Interior
                                                 : ShadowRegion::Silhouette;
}

// F_{Z_t}(z) of the texel at (x, y): the light its ray loses in front of z (docs/reference.md §7).
// Opaque texels, and the far plane outside the map, are one atom of mass 1: the hard test.
double texel_cdf(const ShadowMap& map, int x, int y, double z);

// One receiver's test at texel (x, y) of `map`, its depth z_f and plane gradient (dz/dx, dz/dy
// in texels): z_f - delta_f, F_Z there (the oracle) and the reference (docs/reference.md §3).
struct ReceiverTest {
  double ztest, oracle, pcf;
  int covered_taps;  // taps with a surface in front of ztest (ShadowRegion)
};
ReceiverTest receiver_test(const ShadowMap& map, const GaussianKernel& kernel,
                           const BiasParams& bias, int x, int y, double zf, double gx, double gy);

// Receivers in texel order, then layer order; identical for every thread count.
Fragments collect_receivers(const LayerStack& stack, const GaussianKernel& kernel,
                            const BiasParams& bias, int threads);

// The depth distribution Z the kernel sees around texel (x, y): size^2 layer-0 depths and their
// weights, written to `depths` and `weights` (each kernel.size^2 long), in tap order (rows, then
// columns). With `texels`, also each tap's texel index, or width * height for taps outside the map.
void kernel_distribution(const ShadowMap& map, const GaussianKernel& kernel, int x, int y,
                         std::span<double> depths, std::span<double> weights,
                         std::span<size_t> texels = {});

// The kernel's distribution over the atoms of its taps' texels (docs/reference.md §7): for an
// opaque map exactly kernel_distribution's taps; for a translucent one, tap by tap, each atom of
// the tap's texel with weight k_t * its blended mass (ShadowMap::blended_mass). With `atoms`, each
// one's global index (atom_count() for taps outside the map); with `tap_offsets`, where each tap's
// atoms begin (size^2 + 1 entries); with `alphas`, each atom's opacity (ShadowMap::atom_alpha; an
// opaque map's texels 1, the far plane 0).
void kernel_atoms(const ShadowMap& map, const GaussianKernel& kernel, int x, int y,
                  std::vector<double>& depths, std::vector<double>& weights,
                  std::vector<size_t>* atoms = nullptr,
                  std::vector<uint32_t>* tap_offsets = nullptr,
                  std::vector<double>* alphas = nullptr);

}  // namespace mb
