#pragma once
// A whole sweep (docs/sweeps.md): the references once, then every candidate of this shard exactly,
// or screened on a sample with the candidates in reach of the best confirmed exactly. Every row is
// committed on its own, so a killed sweep resumes from any instant, losing and repeating nothing.
// `sweep` parses its flags into SweepSettings and calls run_sweep; tests call it directly.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "eval/evaluation.h"
#include "scatter/scatter_run.h"
#include "screen/screening.h"
#include "techniques/oit/oit_technique.h"
#include "util/config.h"

namespace mb {

struct ScreenSettings {
  double fraction = 0;  // screen.fraction: 0 = every candidate exactly
  double refine = 0;    // screen.refine: a second sample's share, 0 = none
  int top = 0;          // screen.top, screen.sigmas, screen.margin: the confirmation rule
  double sigmas = 0, margin = 0;
  uint64_t seed = 0;       // screen.seed
  double keep_sigmas = 0;  // screen.keep_sigmas: which unit errors a shard keeps
  ScreenRule rule() const { return {top, sigmas, margin}; }
};

// The sweep's options as typed fields (sweep_specs declares them).
struct SweepSettings {
  EvalSettings eval;
  std::string target;                       // sweep_target.h: shadows, transparency or scattering
  std::vector<std::string> oit_references;  // the transparency target's reference rows
  std::vector<std::string> scatter_references;  // the scattering target's
  ScatterRunOptions scatter;                    // the scattering target's scatter.* options
  // Their MBOIT overestimation (oit.beta), the warped depth of every technique (oit.warp) and the
  // candidates' LP (lp.*).
  OitParams oit;
  std::string dataset;
  int resolution = 0;
  std::vector<std::string> catalog, candidates, references;
  int combination_size = 0;
  uint64_t sample = 0, sample_seed = 0;
  ScreenSettings screen;
  std::string config_yaml;        // the effective config: the run's identity (run_identity.h)
  std::vector<OptionSpec> specs;  // every option of the sweep: which of them are its identity
};
// The sweep's own options (after the dataset's and the shadow options), declared once: the
// candidates' keys bound to SweepSettings, the screen's to ScreenSettings.
std::vector<OptionSpec> sweep_option_specs();
// The options a sweep of `target` reads (docs/sweeps.md "Identity"): its own, the screen's and
// the measurement's of that target, for a shadow target the hard shadow's
// (hard_shadow_option_specs: no soft.* nor light.directions, which only an area light reads, and
// a shadow sweep refuses one), for a transparency target the oit.* and lp.* options (no light
// view: neither `resolution` nor the kernel's keys). Two series of one target are compared on
// these.
std::vector<OptionSpec> sweep_target_specs(const std::string& target);
SweepSettings sweep_settings_from(const Config& config, int threads);

struct SweepJob {
  std::filesystem::path out;
  int shard = 1, shards = 1;
  bool resume = false, force = false, quiet = false;
  std::vector<std::string> arguments;  // this process's, for run_<time>.yaml
};

// Runs the sweep into job.out (its state: created, or resumed when job.resume and the config is
// the same). Input errors are raised before anything is written.
void run_sweep(const SweepSettings& settings, const SweepJob& job);

}  // namespace mb
