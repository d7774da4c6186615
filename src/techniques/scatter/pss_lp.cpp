// pss_lp:<basis> (docs/scattering.md §3.2): Problem 1 on the row-prefiltered moments of any basis.
// The prefix sums of a rectified row are the moments of a distribution of depths — the row's texels
// up to the ray's end, weighted by transmittance (docs/scattering.md §3.2) — so the shadowed
// fraction of the ray is that distribution's CDF at the ray's depth, and the LP bounds it sharply
// for any basis: beta 0 (scatter.beta) the sharp lower bound, never too dark against pss_exact; 1
// the sharp upper bound; between them the blend. The LP is the project's one fragment solver
// (techniques/lp_fragment_solver.h), through the lp:<basis> technique, with the ray's own
// distribution as the kernel's: its depths join the grid, so the program is feasible by
// construction and the answer is Problem 1 for exactly the moments a prefix sum holds.
#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "moments/storage.h"
#include "techniques/lp_technique.h"
#include "techniques/registry.h"
#include "techniques/scatter/prefiltered_scatter.h"
#include "util/error.h"
#include "util/name_list.h"
#include "util/number_text.h"

namespace mb {

namespace {

constexpr std::string_view kPrefix = "pss_lp:", kStoredPrefix = "pss_lp_stored:";

std::string lp_name_of(const std::string& name) {
  return "lp:" + name.substr(kPrefix.size());
}

class PssLp : public PrefilteredScatter {
 public:
  // `stored`: pss_lp_stored:<row>, the LP over the moment box of that row's stored map.
  PssLp(const std::string& name, const ScatterParams& params,
        std::optional<StoredFormat> stored = std::nullopt)
      : PrefilteredScatter(name, params),
        lp_name_(stored ? lp_technique_name(joined(stored->basis, "; ")) : lp_name_of(name)),
        stored_(std::move(stored)),
        instance_(next_instance()),
        technique_(params.technique) {
    technique_.lp_beta = params.beta;  // scatter.beta is the one beta of the family
    make_lp(technique_);               // a bad basis, or a beta the box cannot take, fails here
    std::lock_guard<std::mutex> lock(live_mutex());
    live().insert(instance_);
  }
  ~PssLp() override {
    std::lock_guard<std::mutex> lock(live_mutex());
    live().erase(instance_);
  }
  size_t failures() const override { return failures_; }

 protected:
  // pss_lp_stored: what the stored map holds, the rows' prefix sums of the basis rounded through
  // the format (as the stored row's own prefilter keeps them), whose mean along a ray centres the
  // ray's box (docs/scattering.md §3.2).
  void prefilter(const RectifiedMap& map) override {
    if (!stored_) return;
    const Basis basis = Basis::parse(stored_->basis);
    sums_ = std::make_unique<RowPrefixSums>(map, int(basis.size()), [basis](double z, double* out) {
      for (size_t j = 0; j < basis.size(); ++j) out[j] = basis[j](z);
    });
    sums_->round_through(stored_->storage);
  }
  double shadowed_fraction(const RectifiedRay& ray) const override {
    Scratch& scratch = this->scratch();
    ray_distribution(map(), ray, scratch.depths, scratch.weights);
    merge_equal_depths(scratch);
    double total = 0;
    for (double w : scratch.weights) total += w;
    for (double& w : scratch.weights) w /= total;
    FragmentInput in;
    in.kernel_depths = scratch.depths, in.kernel_weights = scratch.weights, in.zf = ray.depth;
    if (sums_) {
      scratch.mean.resize(size_t(sums_->channels()));
      sums_->mean(ray, scratch.mean.data());
      scratch.stored = stored_values(stored_->storage, scratch.mean);
      in.stored_values = scratch.stored;
    }
    const size_t before = scratch.lp->failures();
    const double g = scratch.lp->shadow(in);
    if (scratch.lp->failures() == before) return g;
    // The same program once more in exact (rational) arithmetic: the rows' degenerate programs
    // (one to three distinct depths, on the moment cone's boundary) that a floating-point
    // backend cannot certify, it can, at about 300 times the cost of one LP, paid by the
    // few rays that need it (docs/scattering.md §3.2).
    if (technique_.lp_backend != "exact" && !stored_) {
      if (!scratch.exact_lp) {
        TechniqueParams exact = technique_;
        exact.lp_backend = "exact";
        scratch.exact_lp = make_lp(exact);
      }
      const size_t exact_before = scratch.exact_lp->failures();
      const double exact_g = scratch.exact_lp->shadow(in);
      if (scratch.exact_lp->failures() == exact_before) return exact_g;
    }
    // No certified answer: counted, and answered as lit, as closed forms answer a NaN.
    std::lock_guard<std::mutex> lock(mutex_);
    ++failures_;
    return 0;
  }

 private:
  // An LP technique is not thread-safe, and its GLPK objects must be freed by the thread that
  // made them: each thread keeps its own per technique instance, made on first use. Each answers
  // from scratch, so which thread answers a ray changes no bit. A sweep makes an instance per
  // candidate: a thread frees what it made for instances since destroyed when it first serves a
  // new one, so that it holds LPs only for live instances.
  struct Scratch {
    std::unique_ptr<Technique> lp, exact_lp;  // exact_lp: made on a ray `lp` cannot certify
    std::vector<double> depths, weights;
    std::vector<std::pair<double, double>> atoms;
    std::vector<double> mean, stored;  // pss_lp_stored: the ray's rounded mean, as stored
  };
  // The same distribution with each depth once (its weights summed) and no empty atoms. A row
  // repeats depths by the hundred (texels of one surface, the clamped ends 0 and 1), and each
  // copy is another equal column of the LP: degenerate programs the solver could fail to certify,
  // answered lit (docs/scattering.md §3.2). Merging changes the problem not at all.
  static void merge_equal_depths(Scratch& s) {
    s.atoms.clear();
    for (size_t i = 0; i < s.depths.size(); ++i)
      if (s.weights[i] > 0) s.atoms.emplace_back(s.depths[i], s.weights[i]);
    std::sort(s.atoms.begin(), s.atoms.end());
    s.depths.clear(), s.weights.clear();
    for (const auto& [depth, weight] : s.atoms) {
      if (!s.depths.empty() && s.depths.back() == depth)
        s.weights.back() += weight;
      else
        s.depths.push_back(depth), s.weights.push_back(weight);
    }
  }
  static uint64_t next_instance() {
    static std::atomic<uint64_t> count{0};
    return ++count;
  }
  static std::set<uint64_t>& live() {
    static std::set<uint64_t> instances;
    return instances;
  }
  static std::mutex& live_mutex() {
    static std::mutex mutex;
    return mutex;
  }
  Scratch& scratch() const {
    thread_local std::map<uint64_t, Scratch> per_instance;
    const auto found = per_instance.find(instance_);
    if (found != per_instance.end()) return found->second;
    {
      std::lock_guard<std::mutex> lock(live_mutex());
      std::erase_if(per_instance, [](const auto& entry) { return !live().count(entry.first); });
    }
    Scratch& s = per_instance[instance_];
    s.lp = make_lp(technique_);
    return s;
  }
  std::unique_ptr<Technique> make_lp(const TechniqueParams& p) const {
    if (!stored_) return make_lp_technique(lp_name_, p);
    return make_lp_technique(lp_name_, Basis::parse(stored_->basis), stored_->storage, p);
  }

  std::string lp_name_;
  std::optional<StoredFormat> stored_;
  std::unique_ptr<RowPrefixSums> sums_;  // pss_lp_stored: the stored map's prefix sums
  uint64_t instance_;
  TechniqueParams technique_;  // the LP's settings (lp.*) with lp.beta = scatter.beta
  mutable std::mutex mutex_;
  mutable size_t failures_ = 0;
};

// pss_lp_stored:<row>: the row's stored format (a scattering row of its own whose map is not
// double), made with the same parameters, as lp_stored: reads a hard-shadow row's storage().
std::unique_ptr<ScatterTechnique> make_stored(const std::string& name,
                                              const ScatterParams& params) {
  const std::string inner = name.substr(kStoredPrefix.size());
  const TechniqueRow* row = find_technique(inner, TechniqueFamily::Scattering);
  std::optional<ScatterTechnique::StoredFormat> format;
  if (row && !row->prefix() && !row->solves_lp && row->make_scatter)
    format = row->make_scatter(inner, params)->stored_format();
  if (!format) {
    std::vector<std::string> valid;
    for (const TechniqueRow* r : family_rows(TechniqueFamily::Scattering))
      if (!r->prefix() && !r->solves_lp && r->make_scatter &&
          r->make_scatter(r->name, params)->stored_format())
        valid.push_back(r->name);
    throw InputError("technique '" + name +
                     "': expected pss_lp_stored:<a scattering row with a stored format>, one of " +
                     joined(valid, ", "));
  }
  // The box answers the sharp lower bound alone (docs/reference.md §2): a blend towards an upper
  // bound it does not solve must not pass as measured.
  if (params.beta != 0)
    throw InputError("technique '" + name + "': scatter.beta = " + round_trip(params.beta) +
                     ", but the moment box answers the sharp lower bound only; expected "
                     "scatter.beta = 0 (its default, 0.5, blends towards the upper bound)");
  return std::make_unique<PssLp>(name, params, std::move(format));
}

std::vector<TechniqueRow> rows() {
  return {
      {.name = std::string(kPrefix),
       .family = TechniqueFamily::Scattering,
       .rank = 60,
       .summary = "Problem 1 on the rectified row's prefix-summed moments of any basis, through "
                  "the LP fragment solver; scatter.beta blends its sharp bounds on the "
                  "shadowed fraction (docs/scattering.md §3.2)",
       .storage = "rectified map, prefix sums in double",
       .bound = "at scatter.beta 0 never too dark against pss_exact (the LP's certified "
                "tolerance)",
       .unproven_reason = "scatter.beta > 0 blends towards the upper bound, and pss_exact "
                          "itself is not the exact reference",
       .family_options = {"scatter.light_resolution", "scatter.guard_band", "scatter.resample",
                          "scatter.beta", "lp.grid", "lp.discretization", "lp.backend"},
       .default_run = true,
       .example = "pss_lp:power4",
       .solves_lp = true,
       .make_scatter = [](const std::string& name, const ScatterParams& params)
           -> std::unique_ptr<ScatterTechnique> { return std::make_unique<PssLp>(name, params); }},
      {.name = std::string(kStoredPrefix),
       .family = TechniqueFamily::Scattering,
       .rank = 62,
       .summary = "Problem 1 on the rectified row's prefix sums over the moment box of a stored "
                  "row's own map (its basis, transform and bits), e.g. "
                  "pss_lp_stored:pss_msm6_10bit: the least a reconstruction reading that map can "
                  "lose (docs/scattering.md §3.2)",
       .storage = "the named row's",
       .bound = "at scatter.beta 0 never too dark against pss_exact: the ray's own moments lie "
                "in the box",
       .family_options = {"scatter.light_resolution", "scatter.guard_band", "scatter.resample",
                          "lp.grid", "lp.discretization"},
       .example = "pss_lp_stored:pss_msm6_10bit",
       .solves_lp = true,
       .make_scatter = make_stored,
       .parameter = "<technique>"}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
