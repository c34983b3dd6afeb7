#include "panel.hpp"

#include "command_line.hpp"

#include "exec/param_sidecar.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

namespace pl::lab {

namespace {

using graph::ParamType;

// A slider needs a range; params without one get a drag widget instead (unbounded).
bool param_widget(graph::ParamDesc& p) {
    const char* label = p.name.c_str();
    float f[4];
    for (int i = 0; i < 4; ++i) f[i] = static_cast<float>(p.value[static_cast<size_t>(i)]);
    bool ranged = p.min && p.max && *p.min < *p.max;
    float lo = ranged ? static_cast<float>(*p.min) : 0.0f, hi = ranged ? static_cast<float>(*p.max) : 0.0f;
    // Log sliders spread decades evenly (roughness 0.001..1, exposure, frequencies).
    ImGuiSliderFlags flags = p.log ? ImGuiSliderFlags_Logarithmic : 0;
    bool changed = false;
    switch (p.type) {
    case ParamType::boolean: {
        bool b = p.value[0] != 0.0;
        changed = ImGui::Checkbox(label, &b);
        f[0] = b ? 1.0f : 0.0f;
        break;
    }
    case ParamType::enumeration: {
        int i = static_cast<int>(p.value[0]);
        if (ImGui::BeginCombo(label, i >= 0 && i < static_cast<int>(p.options.size()) ? p.options[static_cast<size_t>(i)].c_str() : "?")) {
            for (int k = 0; k < static_cast<int>(p.options.size()); ++k)
                if (ImGui::Selectable(p.options[static_cast<size_t>(k)].c_str(), k == i)) i = k, changed = true;
            ImGui::EndCombo();
        }
        f[0] = static_cast<float>(i);
        break;
    }
    case ParamType::i32: {
        int i = static_cast<int>(p.value[0]);
        changed = ranged ? ImGui::SliderInt(label, &i, static_cast<int>(lo), static_cast<int>(hi))
                         : ImGui::DragInt(label, &i, 0.2f);
        f[0] = static_cast<float>(i);
        break;
    }
    case ParamType::color3: changed = ImGui::ColorEdit3(label, f, ImGuiColorEditFlags_Float); break;
    case ParamType::color4: changed = ImGui::ColorEdit4(label, f, ImGuiColorEditFlags_Float); break;
    default: {
        int n = p.components();
        if (ranged) {
            changed = n == 1   ? ImGui::SliderFloat(label, f, lo, hi, "%.4g", flags)
                      : n == 2 ? ImGui::SliderFloat2(label, f, lo, hi, "%.3g", flags)
                      : n == 3 ? ImGui::SliderFloat3(label, f, lo, hi, "%.3g", flags)
                               : ImGui::SliderFloat4(label, f, lo, hi, "%.3g", flags);
        } else {
            // Speed proportional to the magnitude so both 0.01 and 100 are draggable.
            float speed = std::max(0.001f, std::fabs(f[0]) * 0.01f);
            changed = n == 1   ? ImGui::DragFloat(label, f, speed, 0, 0, "%.4g")
                      : n == 2 ? ImGui::DragFloat2(label, f, speed, 0, 0, "%.3g")
                      : n == 3 ? ImGui::DragFloat3(label, f, speed, 0, 0, "%.3g")
                               : ImGui::DragFloat4(label, f, speed, 0, 0, "%.3g");
        }
    }
    }
    if (!p.doc.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p.doc.c_str());
    if (changed)
        for (int i = 0; i < 4; ++i) p.value[static_cast<size_t>(i)] = f[i];
    return changed;
}

void params_section(LabState& s, exec::Executor& ex, const std::string& preset) {
    auto& params = ex.params();
    if (params.empty()) {
        ImGui::TextDisabled("this preset has no [params]");
        return;
    }
    for (auto& p : params)
        if (param_widget(p)) s.touched[p.name] = p.value;
    if (ImGui::Button("Copy as --set")) {
        s.copy_line = render_command(self_executable(), preset, set_arguments(ex, s));
        ImGui::SetClipboardText(s.copy_line.c_str());
        s.status = "copied: " + s.copy_line;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the command line that renders these values");
    ImGui::SameLine();
    if (ImGui::Button("Save")) s.save_sidecar = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("save to a sidecar file the next `passlab run` applies (preset.toml is never written)");
    ImGui::SameLine();
    if (ImGui::Button("Reset")) s.reset_params = true;
}

void time_section(LabState& s) {
    ImGui::Checkbox("pause (space)", &s.paused);
    ImGui::SameLine();
    if (ImGui::Button("step (->)")) s.step = true;
    float t = static_cast<float>(s.time);
    if (ImGui::DragFloat("time", &t, 0.01f, 0.0f, 0.0f, "%.3f s")) s.time = t;  // scrub
    ImGui::SliderFloat("speed", &s.speed, 0.0f, 4.0f, "%.2fx");
    if (ImGui::Button("reset camera")) s.reset_camera = true;
    ImGui::SameLine();
    if (ImGui::Button("screenshot (F12)")) s.screenshot = true;
}

void passes_section(LabState& s, const exec::Executor& ex) {
    const auto& g = ex.graph();
    double total = 0;
    if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("kind");
        ImGui::TableSetupColumn("GPU ms");
        ImGui::TableHeadersRow();
        for (size_t i : g.order) {
            const auto& pd = *g.passes[i].desc;
            double ms = 0;
            for (const auto& t : ex.timings())
                if (t.name == pd.name) ms = t.gpu_ms;
            total += ms;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(pd.name.c_str());
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", graph::kind_name(pd.kind));
            ImGui::TableNextColumn();
            ImGui::Text("%7.3f", ms);
        }
        ImGui::EndTable();
    }
    ImGui::Text("GPU total %.2f ms", total);
    if (!s.frame_ms.empty()) {
        std::vector<float> v(s.frame_ms.begin(), s.frame_ms.end());
        float mx = *std::max_element(v.begin(), v.end());
        char label[64];
        std::snprintf(label, sizeof label, "CPU frame %.1f ms", v.back());
        ImGui::PlotLines("##frame", v.data(), static_cast<int>(v.size()), 0, label, 0.0f, mx * 1.2f, ImVec2(0, 60));
    }
}

// The images in the order passes write them ("pass: image"), then those no pass writes
// (textures, inputs). Multisampled images are left out: the viewer reads their resolve.
std::vector<std::pair<std::string, std::string>> images_in_pass_order(const exec::Executor& ex) {
    const auto& images = ex.resources().images;
    const auto& g = ex.graph();
    std::vector<std::pair<std::string, std::string>> out;  // (image, label)
    std::set<std::string> listed;
    auto add = [&](const std::string& name, const std::string& label) {
        auto it = images.find(name);
        if (it == images.end() || listed.count(name)) return;
        if (it->second.phys[0] && it->second.phys[0]->image.info().samples != VK_SAMPLE_COUNT_1_BIT) return;
        listed.insert(name);
        out.emplace_back(name, label);
    };
    for (size_t i : g.order)
        for (const auto& w : g.passes[i].io.writes) add(w, g.passes[i].desc->name + ": " + w);
    for (const auto& [name, gi] : images) add(name, name);
    return out;
}

void viewer_stats_section(LabState& s) {
    const ImageStats& st = s.viewer_stats;
    if (ImGui::BeginTable("stats", 4, ImGuiTableFlags_SizingFixedFit)) {
        const char* names[] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c) {
            ImGui::TableNextColumn();
            ImGui::Text("%s", names[c]);
            ImGui::TableNextColumn();
            ImGui::Text("min %.4g", st.min[c]);
            ImGui::TableNextColumn();
            ImGui::Text("max %.4g", st.max[c]);
            ImGui::TableNextColumn();
            ImGui::Text("mean %.4g", st.mean[c]);
        }
        ImGui::EndTable();
    }
    if (st.nonfinite) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%zu of %zu texels are NaN or Inf (shown white)", st.nonfinite, st.texels);
    if (!st.histogram.empty()) {
        char label[96];
        std::snprintf(label, sizeof label, "%.4g .. %.4g%s", st.lo, st.hi, st.log_scale ? " (log2 bins)" : "");
        ImGui::PlotHistogram("##hist", st.histogram.data(), static_cast<int>(st.histogram.size()), 0, label, 0.0f, FLT_MAX, ImVec2(0, 60));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s of the finite texels in %zu equal bins", s.viewer_mapping.channel ? "the channel" : "luminance (Rec. 709)",
                              st.histogram.size());
        ImGui::Text("99%% of texels <= %.4g: auto EV %+.2f", st.p99, auto_exposure_ev(st));
    }
}

void viewer_section(LabState& s, const exec::Executor& ex) {
    ImGui::Checkbox("show in the window", &s.show_viewer);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the window shows this image instead of the output: wheel zooms, drag pans, hover reads texels");
    const auto& images = ex.resources().images;
    if (s.viewer_image.empty() || !images.count(s.viewer_image)) s.viewer_image = ex.graph().desc.output;
    const auto listed = images_in_pass_order(ex);
    std::string current = s.viewer_image;
    for (const auto& [name, label] : listed)
        if (name == s.viewer_image) current = label;
    if (ImGui::BeginCombo("image", current.c_str())) {
        for (const auto& [name, label] : listed)
            if (ImGui::Selectable(label.c_str(), name == s.viewer_image)) s.viewer_image = name, s.viewer_mip = s.viewer_layer = 0;
        ImGui::EndCombo();
    }
    auto it = images.find(s.viewer_image);
    if (it == images.end()) return;
    const auto& gi = it->second;
    bool is3d = gi.desc && gi.desc->kind == graph::ImageKind::tex3d;
    int mips = static_cast<int>(gi.mips), layers = static_cast<int>(is3d ? gi.extent.depth : gi.layers);
    if (mips > 1) ImGui::SliderInt("mip", &s.viewer_mip, 0, mips - 1);
    if (layers > 1) ImGui::SliderInt(is3d ? "slice" : (layers == 6 ? "layer / face" : "layer"), &s.viewer_layer, 0, layers - 1);
    s.viewer_mip = std::clamp(s.viewer_mip, 0, mips - 1);
    s.viewer_layer = std::clamp(s.viewer_layer, 0, std::max(0, (is3d ? std::max(1, layers >> s.viewer_mip) : layers) - 1));
    const char* channels[] = {"RGB", "R", "G", "B", "A"};
    ImGui::Combo("channel", &s.viewer_mapping.channel, channels, 5);
    ImGui::BeginDisabled(s.viewer_auto_exposure);
    ImGui::SliderFloat("exposure EV", &s.viewer_mapping.exposure_ev, -10.0f, 10.0f, "%+.1f");
    ImGui::EndDisabled();
    ImGui::Checkbox("auto exposure", &s.viewer_auto_exposure);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("every frame, the EV that maps the 99th percentile of the shown value to white (HDR images)");
    ImGui::Checkbox("encode sRGB for display", &s.viewer_mapping.encode_srgb);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("on for linear (float/unorm) data, off for images that already hold sRGB-encoded values");
    ImGui::TextDisabled("%ux%u, %u mip(s), %u layer(s), %s", gi.extent.width, gi.extent.height, gi.mips, gi.layers,
                        gi.desc ? gi.desc->format.c_str() : "");
    if (!s.show_viewer) return;
    {
        const ImGuiIO& io = ImGui::GetIO();
        const FitRect r = view_rect(s.viewer_view, s.viewer_pixels.width, s.viewer_pixels.height,
                                    static_cast<int>(io.DisplaySize.x * io.DisplayFramebufferScale.x) - s.dock_px,
                                    static_cast<int>(io.DisplaySize.y * io.DisplayFramebufferScale.y));
        ImGui::Text("zoom %.3gx%s (wheel; drag pans)", r.scale, s.viewer_view.fitted ? ", fitted" : "");
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("fit")) s.viewer_view.fitted = true;
    viewer_stats_section(s);
}

// The viewer fills the view: the texel under the cursor, with its float value, as a tooltip.
void viewer_hover(const LabState& s, const ViewerTexture& v) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse) return;
    float fx = io.DisplayFramebufferScale.x, fy = io.DisplayFramebufferScale.y;
    FitRect r = view_rect(s.viewer_view, v.width(), v.height(), static_cast<int>(io.DisplaySize.x * fx) - s.dock_px,
                          static_cast<int>(io.DisplaySize.y * fy));
    const auto [x, y] = texel_at(r, io.MousePos.x * fx - s.dock_px, io.MousePos.y * fy);
    const image::Image& px = s.viewer_pixels;
    if (x < 0 || y < 0 || x >= px.width || y >= px.height) return;
    const float* c = px.at(x, y);
    ImGui::SetTooltip("%s mip %d layer %d  (%d, %d)\n%.5g  %.5g  %.5g  %.5g", s.viewer_image.c_str(), s.viewer_mip, s.viewer_layer, x, y,
                      c[0], c[1], c[2], c[3]);
}

void error_overlay(const Error& e) {
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f, vp->Pos.y + vp->Size.y - 10), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    // Full width: the source line and its caret must not wrap (they are aligned by column).
    ImGui::SetNextWindowSizeConstraints(ImVec2(vp->Size.x - 20, 0), ImVec2(vp->Size.x - 20, vp->Size.y * 0.6f));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.25f, 0.02f, 0.02f, 0.92f));
    ImGui::Begin("Reload failed: showing the last good frame", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing |
                     ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.7f, 1.0f));
    // The same text the terminal shows: file:line:col, pass, resource, the source line, a caret.
    ImGui::TextUnformatted(e.format().c_str());
    ImGui::PopStyleColor();
    ImGui::TextDisabled("fix the file and save: the overlay clears on the next good build");
    ImGui::End();
    ImGui::PopStyleColor();
}

void help_window(LabState& s) {
    ImGui::Begin("Keys", &s.show_help, ImGuiWindowFlags_AlwaysAutoResize);
    const char* rows[][2] = {{"drag", "orbit the camera (image viewer: pan)"}, {"wheel", "zoom (image viewer: about the cursor)"},
                             {"space", "pause / resume time"},   {"->", "step one frame (1/60 s) while paused"},
                             {"F12", "output and window PNGs (never overwrites)"}, {"Tab", "hide / show the panel"},
                             {"F1", "this help"},                {"Esc", "quit"}};
    for (auto& r : rows) {
        ImGui::TextUnformatted(r[0]);
        ImGui::SameLine(80);
        ImGui::TextDisabled("%s", r[1]);
    }
    ImGui::End();
}

} // namespace

std::vector<std::string> set_arguments(const exec::Executor& ex, const LabState& s) {
    std::vector<std::string> out;
    for (const auto& p : ex.graph().desc.params) {
        auto it = s.touched.find(p.name);
        if (it != s.touched.end()) out.push_back(p.name + "=" + exec::format_param_value(p, it->second));
    }
    return out;
}

void draw_panel(LabState& s, exec::Executor& ex, const ViewerTexture* viewer, const std::string& preset) {
    if (s.error) error_overlay(*s.error);
    if (s.show_help) help_window(s);
    if (!s.show_ui) return;
    // Docked: the full height of the window's left strip, which run.cpp keeps out of the view.
    // It never comes to the front, so the error overlay stays drawn above it.
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(s.dock_px) / io.DisplayFramebufferScale.x, io.DisplaySize.y), ImGuiCond_Always);
    ImGui::Begin("passlab", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus);
    ImGui::TextDisabled("%s", preset.c_str());
    if (ImGui::CollapsingHeader("Params", ImGuiTreeNodeFlags_DefaultOpen)) params_section(s, ex, preset);
    if (ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) time_section(s);
    if (ImGui::CollapsingHeader("Passes", ImGuiTreeNodeFlags_DefaultOpen)) passes_section(s, ex);
    if (ImGui::CollapsingHeader("Cameras", ex.graph().desc.cameras.empty() ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) cameras_section(ex);
    // Open from the start when the lab was asked to inspect an image (--inspect).
    if (ImGui::CollapsingHeader("Images", s.show_viewer ? ImGuiTreeNodeFlags_DefaultOpen : 0)) viewer_section(s, ex);
    if (!s.status.empty()) ImGui::TextWrapped("%s", s.status.c_str());
    ImGui::TextDisabled("F1 keys, Tab hides this panel");
    ImGui::End();

    if (s.show_viewer && viewer && viewer->ready()) viewer_hover(s, *viewer);
}

} // namespace pl::lab
