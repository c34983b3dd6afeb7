// `passlab gallery -o DIR`: renders every preset's output as a thumbnail, writes an HTML page
// grouped by family (title, summary, image) and a contact-sheet PNG of all thumbnails.
#include "verbs.hpp"

#include "exec/build.hpp"
#include "exec/executor.hpp"
#include "image/image.hpp"
#include "report.hpp"
#include "util/files.hpp"
#include "vk/context_slot.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

namespace fs = std::filesystem;

namespace pl::lab {

int gallery(const std::string& out_dir, int width, const CommonOptions& c) {
    if (auto s = check_output_dir(out_dir, "-o"); !s) return report(s.error());
    fs::path root = exec::presets_dir();
    std::vector<fs::path> presets;
    std::error_code ec;
    for (const auto& f : files_under(root))
        if (f.filename() == "preset.toml") presets.push_back(f);
    std::sort(presets.begin(), presets.end());
    if (presets.empty()) {
        Error e = make_error("no presets under " + root.string());
        return report(e);
    }
    vk::ContextOptions co;
    co.device = c.device;
    co.validation = c.validation;
    // A runaway preset costs its thumbnail, not the gallery: the rest render on a fresh device.
    vk::ContextSlot slot(co);
    auto first = slot.get();
    if (!first) return report(first.error());
    const std::string device = (*first)->device_description();
    fs::create_directories(out_dir, ec);

    struct Item {
        std::string family, name, title, summary, file;
        image::Image thumb;
    };
    std::vector<Item> items;
    int failures = 0;
    for (const auto& toml : presets) {
        exec::BuildOptions bo;
        bo.cache_dir = cache_dir(c);
        auto built = exec::build_graph(toml, bo);
        if (!built) {
            ++failures;
            std::fputs(built.error().format().c_str(), stderr);
            continue;
        }
        // Thumbnails keep the preset's aspect ratio at the requested width.
        auto view = built->desc.view.size;
        int h = std::max(1, width * view[1] / std::max(1, view[0]));
        bo.size = std::array<int, 2>{width, h};
        built = exec::build_graph(toml, bo);
        if (!built) {
            ++failures;
            std::fputs(built.error().format().c_str(), stderr);
            continue;
        }
        Item it;
        it.family = built->desc.meta.family.empty() ? "other" : built->desc.meta.family;
        it.name = toml.parent_path().filename().string();
        it.title = built->desc.meta.title.empty() ? it.name : built->desc.meta.title;
        it.summary = built->desc.meta.summary;
        std::string output = built->desc.output;
        auto ctx = slot.get();
        if (!ctx) return report(ctx.error());
        auto ex = exec::Executor::create(**ctx, std::move(built.value()));
        if (!ex) {
            ++failures;
            std::fputs(ex.error().format().c_str(), stderr);
            continue;
        }
        (*ex)->set_timeout(timeout(c));
        exec::FrameInput in;
        in.time = 0.5;
        if (auto s = (*ex)->render(in); !s) {
            ++failures;
            std::fputs(s.error().format().c_str(), stderr);
            continue;
        }
        auto img = (*ex)->read(output);
        if (!img) {
            ++failures;
            std::fputs(img.error().format().c_str(), stderr);
            continue;
        }
        it.file = it.family + "-" + it.name + ".png";
        if (auto s = image::save_image(*img, fs::path(out_dir) / it.file); !s) return report(s.error());
        it.thumb = std::move(img.value());
        items.push_back(std::move(it));
    }

    // HTML, grouped by family.
    std::map<std::string, std::vector<const Item*>> by_family;
    for (const auto& it : items) by_family[it.family].push_back(&it);
    std::ofstream h(fs::path(out_dir) / "index.html");
    h << "<!doctype html><html><head><meta charset=\"utf-8\"><title>passlab gallery</title><style>\n"
         "body{font-family:system-ui,sans-serif;margin:24px;background:#14161a;color:#e8eaed}h2{border-bottom:1px solid #333}\n"
         ".grid{display:flex;flex-wrap:wrap;gap:16px}.card{width:" << width << "px;background:#1f2227;padding:8px;border-radius:6px}\n"
         ".card img{width:100%}.card h3{font-size:15px;margin:6px 0 2px}.card p{font-size:12px;color:#aab}</style></head><body>\n"
         "<h1>passlab gallery</h1><p>" << items.size() << " presets &middot; " << html_escape(device) << "</p>\n";
    for (const auto& [family, list] : by_family) {
        h << "<h2>" << html_escape(family) << "</h2><div class=\"grid\">\n";
        for (const Item* it : list)
            h << "<div class=\"card\"><img src=\"" << it->file << "\"><h3>" << html_escape(it->title) << "</h3><p>"
              << html_escape(it->name) << " &mdash; " << html_escape(it->summary) << "</p></div>\n";
        h << "</div>\n";
    }
    h << "</body></html>\n";

    // Contact sheet: thumbnails in family order, 4 per row, 8 px gaps on a dark background.
    const int cols = 4, gap = 8;
    int cell_h = 0;
    for (const auto& it : items) cell_h = std::max(cell_h, it.thumb.height);
    int rows = (static_cast<int>(items.size()) + cols - 1) / cols;
    image::Image sheet;
    sheet.width = cols * width + (cols + 1) * gap;
    sheet.height = rows * cell_h + (rows + 1) * gap;
    sheet.pixels.assign(static_cast<size_t>(sheet.width) * sheet.height * 4, 0.08f);
    for (size_t i = 3; i < sheet.pixels.size(); i += 4) sheet.pixels[i] = 1.0f;
    int k = 0;
    for (const auto& [family, list] : by_family)
        for (const Item* it : list) {
            int x0 = gap + (k % cols) * (width + gap), y0 = gap + (k / cols) * (cell_h + gap);
            for (int y = 0; y < it->thumb.height; ++y)
                for (int x = 0; x < it->thumb.width && x < width; ++x)
                    for (int ch = 0; ch < 4; ++ch) sheet.at(x0 + x, y0 + y)[ch] = it->thumb.at(x, y)[ch];
            ++k;
        }
    fs::path sheet_file = fs::path(out_dir) / "contact-sheet.png";
    if (auto s = image::save_image(sheet, sheet_file); !s) return report(s.error());
    std::printf("%s\n%s\n", (fs::path(out_dir) / "index.html").string().c_str(), sheet_file.string().c_str());
    if (slot.any_hung()) exit_after_hang(failures ? 1 : 0);
    return failures ? 1 : 0;
}

} // namespace pl::lab
