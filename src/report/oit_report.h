#pragma once
// `oit`'s outputs (docs/transparency.md §4): the error table (stdout and report.md), errors.csv
// with a row per technique and camera and an `all` row per technique, and per camera the
// composites, their CIEDE2000 differences and a contact sheet.
#include <string>
#include <vector>

#include "oit/oit_run.h"
#include "oit/oit_verification.h"

namespace mb {

struct OitReportContext {
  std::string dataset, version, git_sha, compiler, started, settings_text;
  int threads = 0;
  size_t cameras = 0, fragments = 0, pixels = 0;
  std::vector<std::string> non_default;
  std::vector<std::string> sheets;  // contact sheets, relative to the report
  double delta_e_scale = 0;         // oit's option (oit_run_options)
};

struct OitReport {
  std::string table, markdown, errors_csv;
};

OitReport render_oit_report(const OitReportContext& context, const std::vector<OitRow>& overall,
                            const std::vector<OitRow>& per_camera);

// verify's transparency rows (docs/transparency.md §6): a Markdown section for verify.md and
// verify_oit.csv.
std::string oit_verify_section(const std::vector<OitVerifyRow>& rows);
std::string oit_verify_csv(const std::vector<OitVerifyRow>& rows);

// `<base>_reference.png`, `<base>_<technique>.png`, `<base>_<technique>_diff.png` (CIEDE2000 in
// false colour up to `scale`, grey where no transparent fragment lies) and `<base>_sheet.png`:
// the reference, then each technique's composite above its difference, labelled. Returns the
// sheet's file name.
std::string write_oit_images(const OitFrameResult& result,
                             const std::vector<std::string>& techniques, const std::string& base,
                             double scale);

}  // namespace mb
