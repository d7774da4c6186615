#include "report/scatter_report.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "report/colour_bar.h"
#include "report/eval_report.h"
#include "techniques/registry.h"
#include "util/image_writer.h"
#include "util/number_text.h"

namespace mb {

namespace {

std::string table_row(const ScatterRow& r) {
  const ScatterStats& s = r.stats;
  std::ostringstream row;
  row << "| " << r.technique << " | " << r.scene << " | " << r.view << " | " << r.camera << " | "
      << format_number(s.mean_error(), "%.3e") << " | " << format_number(s.too_bright(), "%.3e")
      << " | " << format_number(s.too_dark(), "%.3e") << " | " << format_number(s.max_error, "%.3e")
      << " | " << format_number(r.seconds, "%.3f") << " |";
  return row.str();
}

std::string csv_row(const ScatterRow& r) {
  const ScatterStats& s = r.stats;
  std::ostringstream row;
  row << '"' << r.technique << "\"," << r.scene << "," << r.view << "," << r.camera << ","
      << round_trip(s.mean_error()) << "," << round_trip(s.too_bright()) << ","
      << round_trip(s.too_dark()) << "," << round_trip(s.max_error) << ","
      << format_number(r.seconds, "%.3f") << "\n";
  return row.str();
}

std::string failure_row(const ScatterRow& r) {
  const size_t rays = r.stats.pixels;
  std::ostringstream row;
  row << "| " << r.technique << " | " << r.scene << " | " << r.view << " | " << r.camera << " | "
      << r.failures << " | " << rays << " | "
      << format_number(rays > 0 ? double(r.failures) / double(rays) : 0.0, "%.3e") << " |";
  return row.str();
}

constexpr const char* kHeader =
    "| technique | scene | view | camera | mean error | too bright | too dark | max error | "
    "time s |\n|---|---|---|---|---|---|---|---|---|\n";

float to_srgb(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  return float(c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055);
}

// The 99th percentile of `values` (> 0), or 1: an exposure that a few bright pixels cannot set.
double exposure_of(std::vector<double> values) {
  if (values.empty()) return 1;
  const size_t k = values.size() * 99 / 100;
  std::nth_element(values.begin(), values.begin() + long(k), values.end());
  return values[k] > 0 ? 1 / values[k] : 1;
}

}  // namespace

ScatterReport render_scatter_report(const ScatterReportContext& ctx,
                                    const std::vector<ScatterRow>& overall,
                                    const std::vector<ScatterRow>& per_frame) {
  std::ostringstream table, md, csv;
  table << kHeader;
  for (const auto& r : overall) table << table_row(r) << "\n";
  md << "# Single-scattering evaluation of dataset " << ctx.dataset << "\n\n"
     << "Made by momentbench " << ctx.version << " (git " << ctx.git_sha << "), " << ctx.compiler
     << ", " << ctx.threads << " threads, " << ctx.started << ".\n\n"
     << "**Summary.** " << overall.size() << " techniques on " << ctx.frames
     << " light views and cameras, " << ctx.pixels << " view rays in all.\n\n"
     << "- " << ctx.settings_text << "\n";
  for (const auto& line : ctx.non_default) md << "- option " << line << "\n";
  md << "\nThe reference is " << ctx.reference << ", "
     << technique_row(ctx.reference, TechniqueFamily::Scattering).as_reference
     << ". *mean error*: Σ|I − I_ref| / Σ S_max over the view rays, "
        "S_max the in-scattering of the ray were it lit everywhere (seed 000 §3.2's L1 measure: "
        "a short ray weighs less than a long one); *too bright*, *too dark*: its parts where I > "
        "I_ref and I < I_ref (they sum to it); *max error*: the largest |I − I_ref| / S_max of a "
        "ray.\n\nView rays within "
     << round_trip(ctx.epipole_degrees)
     << "° of the light's axis (scatter.epipole_degrees), where a rectified row shrinks to a "
        "point, are measured like the others and counted here (docs/scattering.md §3.1):\n\n";
  for (const auto& line : ctx.epipole_lines) md << "- " << line << "\n";
  md << "\n## All light views and cameras\n\n"
     << table.str() << "\n## Per light view and camera\n\n"
     << kHeader;
  for (const auto& r : per_frame) md << table_row(r) << "\n";
  md << "\n## Rays a technique could not answer\n\nA ray whose own answer failed (an LP without a "
        "certified answer, a closed form without a canonical distribution) is answered as lit, "
        "I = S_max, and counted here; its error is in the tables above (docs/scattering.md "
        "§3.2). *share*: failed rays / rays.\n\n| technique | scene | view | camera | failed "
        "rays | rays | share |\n|---|---|---|---|---|---|---|\n";
  for (const auto* rows : {&overall, &per_frame})
    for (const auto& r : *rows) md << failure_row(r) << "\n";
  if (!ctx.sheets.empty()) {
    md << "\n## Images\n\nEach sheet shows the reference, then every technique: its final colour "
          "(the surface's radiance attenuated by the medium plus the in-scattering), the "
          "in-scattering alone, and its error |I − I_ref| / S_max in false colour (bar from 0 to "
       << round_trip(ctx.error_scale)
       << "). One exposure per sheet, from the reference. Single images are beside the "
          "sheets, and each light view and camera's rectified map (`*_rectified.png`: normalised "
          "depth in grey, the light rays' distance r to the right, their azimuth down). The "
          "radiances in float: `*_<technique>_inscatter.exr` (I), `*_reference_inscatter.exr` "
          "(I_ref) and `*_smax.exr` (S_max, the in-scattering of the ray without shadows).\n\n";
    for (const auto& sheet : ctx.sheets) md << "![" << sheet << "](images/" << sheet << ")\n\n";
  }
  csv << "technique,scene,view,camera,mean_error,too_bright,too_dark,max_error,time_s\n";
  for (const auto* rows : {&overall, &per_frame})
    for (const auto& r : *rows) csv << csv_row(r);
  return {table.str(), md.str(), csv.str()};
}

std::string write_scatter_images(const ScatterFrameResult& result,
                                 const std::vector<std::string>& techniques,
                                 const std::string& reference, const std::string& base,
                                 double scale) {
  const int w = result.width, h = result.height, label = 18, gap = 4;
  const size_t pixels = size_t(w) * h;
  std::vector<double> brightest(pixels);
  for (size_t p = 0; p < pixels; ++p)
    brightest[p] = result.surface[p].maxCoeff() + result.reference[p];
  const double final_exposure = exposure_of(brightest);
  const double inscatter_exposure = exposure_of(result.reference);
  const auto final_image = [&](const std::vector<double>& inscatter) {
    std::vector<float> rgb(pixels * 3);
    for (size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < 3; ++c)
        rgb[p * 3 + c] = to_srgb((result.surface[p][c] + inscatter[p]) * final_exposure);
    return rgb;
  };
  const auto inscatter_image = [&](const std::vector<double>& inscatter) {
    std::vector<float> rgb(pixels * 3);
    for (size_t p = 0; p < pixels; ++p)
      std::fill_n(rgb.begin() + long(p * 3), 3, to_srgb(inscatter[p] * inscatter_exposure));
    return rgb;
  };
  const auto error_image = [&](const std::vector<double>& inscatter) {
    std::vector<float> rgb(pixels * 3);
    for (size_t p = 0; p < pixels; ++p) {
      const double e =
          result.s_max[p] > 0 ? std::abs(inscatter[p] - result.reference[p]) / result.s_max[p] : 0;
      const auto c = colormap(std::min(1.0, e / scale));
      std::copy(c.begin(), c.end(), rgb.begin() + long(p * 3));
    }
    return rgb;
  };

  const size_t columns = techniques.size() + 1;
  const int cell_w = w + gap, cell_h = label + 3 * h + gap;
  std::vector<float> white(columns * cell_w * size_t(cell_h) * 3, 1.0f);
  OIIO::ImageBuf sheet(OIIO::ImageSpec(int(columns) * cell_w, cell_h, 3, OIIO::TypeDesc::FLOAT),
                       white.data());
  const float black[3] = {0, 0, 0};
  const auto paste = [&](const std::vector<float>& rgb, size_t column, int row) {
    OIIO::ImageBuf tile(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT),
                        const_cast<float*>(rgb.data()));
    OIIO::ImageBufAlgo::paste(sheet, int(column) * cell_w, label + row * h, 0, 0, tile);
  };
  const auto caption = [&](const std::string& text, size_t column) {
    OIIO::ImageBufAlgo::render_text(sheet, int(column) * cell_w + 2, label - 4, text, 14,
                                    "DejaVuSans", black);
  };
  const ColourBar bar = magnitude_bar(scale, "|I - I_ref| / S_max");
  const std::vector<float> ref_final = final_image(result.reference);
  const std::vector<float> ref_inscatter = inscatter_image(result.reference);
  write_image(base + "_reference_final.png", w, h, 3, ref_final);
  write_image(base + "_reference_inscatter.png", w, h, 3, ref_inscatter);
  // The radiances themselves, for comparisons the PNGs' exposure and 8 bits would blur (e.g. two
  // scenes that differ in one object, docs/scattering.md §4).
  const auto radiance = [](const std::vector<double>& v) {
    return std::vector<float>(v.begin(), v.end());
  };
  write_image(base + "_reference_inscatter.exr", w, h, 1, radiance(result.reference));
  write_image(base + "_smax.exr", w, h, 1, radiance(result.s_max));
  paste(ref_final, 0, 0), paste(ref_inscatter, 0, 1);
  caption("reference (" + reference + ")", 0);
  if (result.rectified) {
    const RectifiedMap& map = *result.rectified;
    std::vector<float> grey(size_t(map.width()) * map.height() * 3);
    for (int v = 0; v < map.height(); ++v)
      for (int u = 0; u < map.width(); ++u)
        std::fill_n(grey.begin() + long((size_t(v) * map.width() + u) * 3), 3,
                    float(map.depth(u, v)));
    write_image(base + "_rectified.png", map.width(), map.height(), 3, grey);
  }
  for (size_t k = 0; k < techniques.size(); ++k) {
    const std::string stem = base + "_" + file_stem(techniques[k]);
    const std::vector<float> fin = final_image(result.inscatter[k]);
    const std::vector<float> ins = inscatter_image(result.inscatter[k]);
    const std::vector<float> err = error_image(result.inscatter[k]);
    write_image(stem + "_final.png", w, h, 3, fin);
    write_image(stem + "_inscatter.png", w, h, 3, ins);
    write_image(stem + "_inscatter.exr", w, h, 1, radiance(result.inscatter[k]));
    write_with_colour_bar(stem + "_error.png", err, w, h, bar);
    paste(fin, k + 1, 0), paste(ins, k + 1, 1), paste(err, k + 1, 2);
    caption(techniques[k] + "  " + format_number(result.stats[k].mean_error(), "%.2e"), k + 1);
  }
  std::vector<float> rgb(white.size());
  sheet.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, rgb.data());
  write_with_colour_bar(base + "_sheet.png", rgb, int(columns) * cell_w, cell_h, bar);
  return std::filesystem::path(base + "_sheet.png").filename().string();
}

}  // namespace mb
