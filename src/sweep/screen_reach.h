#pragma once
// Screening at full scale (docs/sweeps.md, "Full scale"): which screened candidates of a results
// database keep their unit errors at a stage (the first, in shards; the refining one, in the
// merged directory), and which of those screened out a sweep cannot prove out of
// reach of its best (screen/screening.h, keeps_unit_errors and proven_out_of_reach).
#include <cstdint>
#include <utility>
#include <vector>

#include "screen/screening.h"
#include "sweep/results_store.h"

namespace mb {

// Drops the unit errors of every estimate of `ids` (ascending) at `stage` in `store` that `rule`
// with `keep_sigmas` does not keep against their own K-th best estimate, keeping reach_lower and
// reach_against instead; never those of a K-th best another estimate was proven against. With
// keep_sigmas >= rule.sigmas what is dropped is out of reach of this K-th best by the
// confirmation's own test, bit for bit; below it, only what a later proof
// (unproven_screened_out) screens again. Returns (screened out now, estimates).
std::pair<size_t, size_t> screen_out_unreachable(ResultsStore& store, int stage,
                                                 const std::vector<uint64_t>& ids,
                                                 const ScreenSample& sample, const ScreenRule& rule,
                                                 double keep_sigmas);

// The estimates of `ids` (ascending) at `stage` to screen again, ascending: those among the best K
// that were screened out (the K-th best's unit errors are every proof's); when none is, every
// screened-out candidate that the K-th best estimate does not prove out of reach. Empty: every
// screened-out candidate is proven out of reach.
std::vector<uint64_t> unproven_screened_out(const ResultsStore& store, int stage,
                                            const std::vector<uint64_t>& ids,
                                            const ScreenSample& sample, const ScreenRule& rule);

// The candidates of `ids` (ascending) without an exact row in `store` whose reported estimate
// (their latest stage's) lies below the best exact mean among `ids`, ascending; empty when none is
// exact. A confirmation that declares ties (screen.margin < 0) leaves estimates within the margin
// of the K-th best unconfirmed; when the confirmed candidates' exact means come out above their
// estimates (chosen for low estimates, they are the lucky ones), such a tie would head the table
// as an estimate (results/FINDINGS.md §13). The sweep evaluates these exactly, until none is left.
std::vector<uint64_t> estimates_ahead_of_best_exact(const ResultsStore& store,
                                                    const std::vector<uint64_t>& ids);

}  // namespace mb
