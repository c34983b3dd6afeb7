// Golden comparison: RMSE, max absolute difference, fraction of pixels over a threshold and
// (optionally) SSIM, with per-case tolerances; missing goldens are written locally and fail in CI.
#pragma once

#include "check/checks.hpp"
#include "image/image.hpp"

namespace pl::check {

CheckResult compare_golden(const image::Image& img, const graph::TestDesc& t, const std::filesystem::path& preset_dir,
                           const RunOptions& opt, const std::filesystem::path& case_id);

} // namespace pl::check
