#include "report/oit_report.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "eval/error_stats.h"
#include "report/colour_bar.h"
#include "report/eval_report.h"
#include "techniques/registry.h"
#include "util/image_writer.h"
#include "util/number_text.h"

namespace mb {

namespace {

std::string table_row(const OitRow& r) {
  const OitStats& s = r.stats;
  std::ostringstream row;
  row << "| " << r.technique << " | " << r.camera << " | " << s.fragments << " | "
      << percent_text(s.transmittance_error()) << " | " << percent_text(s.transmittance_over())
      << " | " << percent_text(s.transmittance_under()) << " | "
      << format_number(s.rgb_error(), "%.5f") << " | " << format_number(s.delta_e_mean(), "%.4f")
      << " | " << format_number(s.delta_e_quantile(0.95), "%.4f") << " | "
      << format_number(s.delta_e_quantile(1), "%.4f") << " | " << s.failures << " |";
  return row.str();
}

std::string csv_row(const OitRow& r) {
  const OitStats& s = r.stats;
  std::ostringstream row;
  row << '"' << r.technique << "\"," << r.camera << "," << s.pixels << "," << s.fragments << ","
      << round_trip(s.transmittance_error()) << "," << round_trip(s.transmittance_over()) << ","
      << round_trip(s.transmittance_under()) << "," << round_trip(s.rgb_error()) << ","
      << round_trip(s.rgb_max) << "," << round_trip(s.delta_e_mean()) << ","
      << round_trip(s.delta_e76_mean()) << "," << round_trip(s.delta_e_quantile(0.5)) << ","
      << round_trip(s.delta_e_quantile(0.95)) << "," << round_trip(s.delta_e_quantile(0.99)) << ","
      << round_trip(s.delta_e_quantile(1)) << "," << s.failures << ","
      << format_number(r.seconds, "%.3f") << "\n";
  return row.str();
}

// The headline: what ran and the lowest error among the approximations.
std::string summary(const OitReportContext& ctx, const std::vector<OitRow>& overall) {
  std::ostringstream s, headline;
  const OitRow* best = nullptr;
  for (const auto& r : overall) {
    headline << (headline.tellp() > 0 ? ", " : "") << r.technique << " "
             << format_number(r.stats.delta_e_mean(), "%.3f");
    if (technique_role(r.technique, {TechniqueFamily::Transmittance}) != RowRole::Reference &&
        (!best || r.stats.delta_e_mean() < best->stats.delta_e_mean()))
      best = &r;
  }
  s << "**Summary.** " << overall.size() << " techniques on dataset " << ctx.dataset << ": "
    << ctx.cameras << " cameras, " << ctx.pixels << " pixels showing transparency, "
    << ctx.fragments << " transparent fragments.  \nMean CIEDE2000: " << headline.str();
  if (best) s << " (lowest: " << best->technique << ")";
  s << ".  \nNeeds attention: ";
  std::ostringstream attention;
  for (const auto& r : overall)
    if (r.stats.failures)
      attention << (attention.tellp() > 0 ? "; " : "") << r.technique << ": " << r.stats.failures
                << " fragments failed (answered T = 1)";
  s << (attention.tellp() > 0 ? attention.str() : std::string("nothing")) << ".\n\n";
  return s.str();
}

constexpr const char* kHeader =
    "| technique | camera | fragments | transmittance error % | over % | under % | RGB error | "
    "mean ΔE00 | ΔE00 p95 | max ΔE00 | failures |\n|---|---|---|---|---|---|---|---|---|---|---|\n";

}  // namespace

OitReport render_oit_report(const OitReportContext& ctx, const std::vector<OitRow>& overall,
                            const std::vector<OitRow>& per_camera) {
  std::ostringstream table, md, csv;
  table << kHeader;
  for (const auto& r : overall) table << table_row(r) << "\n";
  md << "# Transparency evaluation of dataset " << ctx.dataset << "\n\n"
     << "Made by momentbench " << ctx.version << " (git " << ctx.git_sha << "), " << ctx.compiler
     << ", " << ctx.threads << " threads, " << ctx.started << ".\n\n"
     << summary(ctx, overall) << "- " << ctx.settings_text << "\n";
  for (const auto& line : ctx.non_default) md << "- option " << line << "\n";
  md << "\nThe reference is exact sorted compositing (what depth peeling converges to, "
        "docs/transparency.md §1). *Transmittance error*: over every transparent fragment, "
        "|T_ref − T| weighted by its alpha, divided by the sum of alphas, where T is the weight "
        "the technique's composite gives the fragment (after MBOIT's and WBOIT's normalisation); "
        "*over*: the part where T > T_ref (the fragment shows too much), *under*: T < T_ref. "
        "*RGB error*: per pixel showing transparency, the mean over channels of |C − C_ref| in "
        "linear RGB. *ΔE00*: CIEDE2000 between the composites in CIELAB (linear sRGB, D65, "
        "adapted to D50; docs/transparency.md §4); a ΔE00 below about 1 is not visible side by "
        "side.\n\n## All cameras\n\n"
     << table.str() << "\n## Per camera\n\n"
     << kHeader;
  for (const auto& r : per_camera) md << table_row(r) << "\n";
  if (!ctx.sheets.empty()) {
    md << "\n## Images\n\nEach sheet shows the exact composite, then every technique's composite "
          "above its CIEDE2000 difference (colour bar from 0 to "
       << round_trip(ctx.delta_e_scale)
       << "; grey where no transparent fragment lies). Single images are beside the sheets.\n\n";
    for (const auto& sheet : ctx.sheets) md << "![" << sheet << "](images/" << sheet << ")\n\n";
  }
  csv << "technique,camera,pixels,fragments,transmittance_error,transmittance_over,"
         "transmittance_under,rgb_error,rgb_max,delta_e,delta_e76,delta_e_p50,delta_e_p95,"
         "delta_e_p99,delta_e_max,failures,seconds\n";
  for (const auto* rows : {&overall, &per_camera})
    for (const auto& r : *rows) csv << csv_row(r);
  return {table.str(), md.str(), csv.str()};
}

std::string oit_verify_section(const std::vector<OitVerifyRow>& rows) {
  if (rows.empty()) return "";
  std::ostringstream md;
  md << "\n## Transparency: MBOIT's closed forms against the LP\n\n"
        "Each closed form in double with beta = 0 on seeded random pixels (2-13 fragments), "
        "against the continuous LP (certified) with the same basis on the warped depth "
        "(docs/transparency.md §6). *equal*: Hamburger's bound on R, the LP on an interval wide "
        "enough for the canonical nodes; *never below*: the trigonometric reconstruction is one "
        "distribution's mass, never below the sharp bound on the circle, so its T never exceeds "
        "the LP's. An exceedance beyond the tolerance fails verify (exit 5).\n\n"
        "| technique | LP interval | check | pixels | fragments | largest dT | tolerance | beyond "
        "| "
        "LP failures | verdict |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows)
    md << "| " << r.technique << " | [" << format_number(r.lo, "%.6g") << ", "
       << format_number(r.hi, "%.6g") << "] | " << r.kind << " | " << r.pixels << " | "
       << r.fragments << " | " << format_number(r.largest, "%.3g") << " | "
       << format_number(r.tolerance, "%.0e") << " | " << r.beyond << " | " << r.lp_failures << " | "
       << (r.passed() ? "pass" : "**FAIL**") << " |\n";
  return md.str();
}

std::string oit_verify_csv(const std::vector<OitVerifyRow>& rows) {
  std::ostringstream csv;
  csv << "technique,lp_basis,check,lo,hi,pixels,fragments,largest_dT,tolerance,beyond,"
         "lp_failures,passed\n";
  for (const auto& r : rows)
    csv << r.technique << ",\"" << r.lp_basis << "\"," << r.kind << "," << round_trip(r.lo) << ","
        << round_trip(r.hi) << "," << r.pixels << "," << r.fragments << "," << round_trip(r.largest)
        << "," << round_trip(r.tolerance) << "," << r.beyond << "," << r.lp_failures << ","
        << (r.passed() ? "true" : "false") << "\n";
  return csv.str();
}

namespace {

float to_srgb(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1 / 2.4f) - 0.055f;
}

std::vector<float> srgb_image(const std::vector<Rgb>& composite) {
  std::vector<float> rgb(composite.size() * 3);
  for (size_t p = 0; p < composite.size(); ++p)
    for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = to_srgb(composite[p][c]);
  return rgb;
}

std::vector<float> difference_image(const std::vector<float>& delta_e, double scale) {
  std::vector<float> rgb(delta_e.size() * 3, 0.5f);
  for (size_t p = 0; p < delta_e.size(); ++p) {
    if (delta_e[p] < 0) continue;
    const auto c = colormap(std::min(1.0, double(delta_e[p]) / scale));
    for (int ch = 0; ch < 3; ++ch) rgb[p * 3 + ch] = c[ch];
  }
  return rgb;
}

}  // namespace

std::string write_oit_images(const OitFrameResult& result,
                             const std::vector<std::string>& techniques, const std::string& base,
                             double scale) {
  const int w = result.width, h = result.height, label = 18, gap = 4;
  const size_t cells = techniques.size() + 1;
  const int columns = std::max(1, int(std::ceil(std::sqrt(double(cells)))));
  const int rows = int((cells + columns - 1) / columns);
  const int cell_w = w + gap, cell_h = label + 2 * h + gap;
  std::vector<float> white(size_t(columns * cell_w) * (rows * cell_h) * 3, 1.0f);
  OIIO::ImageBuf sheet(OIIO::ImageSpec(columns * cell_w, rows * cell_h, 3, OIIO::TypeDesc::FLOAT),
                       white.data());
  const float black[3] = {0, 0, 0};
  const auto paste = [&](const std::vector<float>& pixels, size_t cell, int row) {
    const int x0 = int(cell % columns) * cell_w, y0 = int(cell / columns) * cell_h;
    OIIO::ImageBuf tile(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT),
                        const_cast<float*>(pixels.data()));
    OIIO::ImageBufAlgo::paste(sheet, x0, y0 + label + row * h, 0, 0, tile);
  };
  const auto caption = [&](const std::string& text, size_t cell) {
    const int x0 = int(cell % columns) * cell_w, y0 = int(cell / columns) * cell_h;
    OIIO::ImageBufAlgo::render_text(sheet, x0 + 2, y0 + label - 4, text, 14, "DejaVuSans", black);
  };
  const ColourBar bar = magnitude_bar(scale, "CIEDE2000 (dE00); grey: no transparency");
  const std::vector<float> reference = srgb_image(result.reference);
  write_image(base + "_reference.png", w, h, 3, reference);
  paste(reference, 0, 0);
  caption("reference (sorted)", 0);
  for (size_t k = 0; k < techniques.size(); ++k) {
    const std::vector<float> image = srgb_image(result.composites[k]);
    const std::vector<float> diff = difference_image(result.delta_e[k], scale);
    const std::string stem = base + "_" + file_stem(techniques[k]);
    write_image(stem + ".png", w, h, 3, image);
    write_with_colour_bar(stem + "_diff.png", diff, w, h, bar);
    paste(image, k + 1, 0);
    paste(diff, k + 1, 1);
    caption(techniques[k] + "  dE00 " + format_number(result.stats[k].delta_e_mean(), "%.3f"),
            k + 1);
  }
  std::vector<float> pixels(white.size());
  sheet.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data());
  write_with_colour_bar(base + "_sheet.png", pixels, columns * cell_w, rows * cell_h, bar);
  return std::filesystem::path(base + "_sheet.png").filename().string();
}

}  // namespace mb
