// Exponential shadow maps: Markov's inequality on exp(c z) (docs/reference.md §4).
#include <algorithm>
#include <cmath>

#include "moments/chebyshev.h"
#include "techniques/technique.h"
#include "util/number_text.h"

namespace mb {

namespace {

class EsmTechnique : public Technique {
 public:
  explicit EsmTechnique(double c)
      : Technique("esm", Basis::parse({"exp(" + round_trip(c) + "*z)"}), double_storage()), c_(c) {}
  double shadow(const FragmentInput& in) override { return esm_bound(in.moments[0], in.zf, c_); }

 private:
  double c_;
};

}  // namespace

std::unique_ptr<Technique> make_esm(const TechniqueParams& p) {
  return std::make_unique<EsmTechnique>(p.esm_c);
}

}  // namespace mb
