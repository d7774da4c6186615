#pragma once
// The images of camera views (camera/camera_views.h): each technique's shadow as a camera sees it,
// its difference from the reference, and a contact sheet of them all.
#include <filesystem>
#include <string>
#include <vector>

#include "camera/camera_views.h"

namespace mb {

// One technique's image: sRGB in [0, 1], 3 channels, row-major. `shadow` per receiver; simple
// diffuse shading with an ambient term under a sky.
std::vector<float> shade_camera_view(const CameraView& view, const std::vector<double>& shadow);
// A technique's difference from PCF: red where it is darker (over-darkening), blue where lighter
// (light leaking), full colour at |G - PCF| >= scale, over the PCF image in grey.
std::vector<float> difference_image(const CameraView& view, const std::vector<double>& shadow,
                                    double scale);

// Writes `<base>_<stem>.png` per technique and `<base>_<stem>_diff.png` per technique that is not
// `references`' (is_view_reference, or an area light's own shadow), and `<base>_sheet.png`: every
// technique's image above its difference, labelled.
void write_camera_images(const CameraView& view, const std::vector<std::string>& names,
                         const std::vector<std::vector<double>>& shadows,
                         const std::vector<bool>& references, const std::string& base,
                         double scale);
// write_camera_images of one camera view into `dir` as <scene>_<light view>_<camera>_*.png.
void write_camera_images(const CameraShadows& shadows, const std::filesystem::path& dir,
                         double scale);

}  // namespace mb
