// The reference itself as table rows: `pcf` (a sanity row, error 0 under the biased reference)
// and `oracle` (F_Z(z_f - delta_f), the floor the bias sets under the receiver-plane reference).
#include <algorithm>
#include <cmath>

#include "techniques/registry.h"

namespace mb {

namespace {

class PcfTechnique : public Technique {
 public:
  PcfTechnique() : Technique("pcf", Basis(), double_storage()) {}
  double shadow(const FragmentInput& in) override { return in.pcf; }
};

// F_Z(z_f - delta_f) itself: every valid lower bound lies below it, so under the receiver-plane
// reference its error is the floor that no technique can go under (docs/reference.md §3).
class OracleTechnique : public Technique {
 public:
  OracleTechnique() : Technique("oracle", Basis(), double_storage()) {}
  double shadow(const FragmentInput& in) override { return in.oracle; }
};

std::vector<TechniqueRow> rows() {
  return {{.name = "pcf",
           .rank = 0,
           .summary = "the reference itself (a sanity row, error 0)",
           .storage = "depth",
           .bound = "0",
           .role = RowRole::Reference,
           .default_run = true,
           .make = [](const std::string&, const TechniqueParams&) -> std::unique_ptr<Technique> {
             return std::make_unique<PcfTechnique>();
           },
           .sweep_references = {{}}},
          {.name = "oracle",
           .rank = 10,
           .summary = "F_Z(z_f - delta_f): the floor the bias sets under receiver_plane",
           .storage = "depth",
           .bound = "0",
           .role = RowRole::BiasFloor,
           .make = [](const std::string&, const TechniqueParams&) -> std::unique_ptr<Technique> {
             return std::make_unique<OracleTechnique>();
           }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
