#include "report.hpp"

#include <algorithm>
#include <fstream>
#include <map>

namespace fs = std::filesystem;

namespace pl::lab {

std::string html_escape(const std::string& s) {
    std::string o;
    for (char c : s) {
        switch (c) {
        case '<': o += "&lt;"; break;
        case '>': o += "&gt;"; break;
        case '&': o += "&amp;"; break;
        case '"': o += "&quot;"; break;
        case '\'': o += "&apos;"; break;
        default:
            // XML 1.0 allows no control character but tab and newline (JUnit files are XML).
            if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') o += "\xEF\xBF\xBD";
            else o += c;
        }
    }
    return o;
}

namespace {

// The report's relative link to `file`: where it is when inside the report folder, else a copy
// at DIR/<name> (name is unique per preset folder and case).
std::string local_copy(const fs::path& dir, const std::string& file, const fs::path& name) {
    if (file.empty()) return {};
    std::error_code ec;
    fs::path src(file);
    if (!fs::exists(src, ec)) return {};
    const fs::path canon_dir = fs::weakly_canonical(dir, ec), canon_src = fs::weakly_canonical(src, ec);
    fs::path rel = canon_src.lexically_relative(canon_dir);
    if (!rel.empty() && *rel.begin() != "..") return rel.generic_string();
    fs::path dst = dir / name;
    fs::create_directories(dst.parent_path(), ec);
    fs::copy_file(src, dst, fs::copy_options::overwrite_existing, ec);
    return ec ? std::string() : name.generic_string();
}

// A folder path as a file-name-safe relative path ("presets/aa/msaa"; ".." becomes "_").
fs::path safe_relative(const std::string& where) {
    fs::path out;
    for (const auto& part : fs::path(where).relative_path()) out /= part == ".." || part == "." ? fs::path("_") : part;
    return out;
}

// The page's behaviour: the filter (failed / all, family), and the image inspector, which opens
// on a click on any thumbnail: the case's rendered, golden and diff images at integer zoom with
// nearest filtering (single pixels visible), a toggle between rendered and golden (space) for
// spotting what moved, and the texel under the cursor; #inspect=<case id> opens it on a case.
constexpr const char* kScript = R"JS(
const rows = [...document.querySelectorAll('tr.case')];
let show = document.body.dataset.defaultShow, family = '';
function apply() {
  let n = 0;
  for (const r of rows) {
    const on = (show === 'all' || r.dataset.status === 'fail') && (!family || r.dataset.family === family);
    r.hidden = !on; n += on;
  }
  document.getElementById('shown').textContent = n + ' of ' + rows.length + ' cases shown';
  for (const b of document.querySelectorAll('[data-show]')) b.classList.toggle('on', b.dataset.show === show);
}
for (const b of document.querySelectorAll('[data-show]')) b.onclick = () => { show = b.dataset.show; apply(); };
document.getElementById('family').onchange = e => { family = e.target.value; apply(); };
for (const a of document.querySelectorAll('#failed a')) a.onclick = () => { family = ''; document.getElementById('family').value = ''; apply(); };
const zoom = document.getElementById('zoom'), zimg = document.getElementById('zimg'), zinfo = document.getElementById('zinfo');
let views = [], at = 0, scale = 4;
function draw() {
  const v = views[at];
  zimg.src = v.src;
  zimg.style.width = zimg.naturalWidth ? zimg.naturalWidth * scale + 'px' : '';
  document.getElementById('ztitle').textContent = v.title + ': ' + v.label + ' (' + scale + 'x)';
  for (const b of document.querySelectorAll('#zviews button')) b.classList.toggle('on', +b.dataset.i === at);
}
zimg.onload = () => { zimg.style.width = zimg.naturalWidth * scale + 'px'; };
function open(row, img) {
  views = [...row.querySelectorAll('figure img')].map(i => ({src: i.src, label: i.dataset.label, title: row.dataset.title}));
  at = Math.max(0, views.findIndex(v => v.src === img.src));
  const bar = document.getElementById('zviews');
  bar.innerHTML = '';
  views.forEach((v, i) => { const b = document.createElement('button'); b.textContent = v.label; b.dataset.i = i; b.onclick = () => { at = i; draw(); }; bar.appendChild(b); });
  zoom.hidden = false; draw();
}
for (const r of rows) for (const i of r.querySelectorAll('figure img')) i.onclick = () => open(r, i);
function flip() {  // rendered <-> golden, where both exist
  const r = views.findIndex(v => v.label === 'rendered'), g = views.findIndex(v => v.label === 'golden');
  if (r >= 0 && g >= 0) { at = at === r ? g : r; draw(); }
}
document.getElementById('zflip').onclick = flip;
document.getElementById('zin').onclick = () => { scale = Math.min(64, scale * 2); draw(); };
document.getElementById('zout').onclick = () => { scale = Math.max(1, scale / 2); draw(); };
document.getElementById('zclose').onclick = () => { zoom.hidden = true; };
document.addEventListener('keydown', e => {
  if (zoom.hidden) return;
  if (e.key === 'Escape') zoom.hidden = true;
  else if (e.key === ' ') { e.preventDefault(); flip(); }
  else if (e.key === '+' || e.key === '=') { scale = Math.min(64, scale * 2); draw(); }
  else if (e.key === '-') { scale = Math.max(1, scale / 2); draw(); }
  else if (e.key >= '1' && e.key <= String(views.length)) { at = +e.key - 1; draw(); }
});
zimg.onmousemove = e => {
  const x = Math.floor(e.offsetX / scale), y = Math.floor(e.offsetY / scale);
  zinfo.textContent = 'texel (' + x + ', ' + y + ') of ' + zimg.naturalWidth + 'x' + zimg.naturalHeight;
};
apply();
// A link to a case's inspector: index.html#inspect=<case id> (shareable; the headless test uses it).
if (location.hash.startsWith('#inspect=')) {
  const r = document.getElementById(decodeURIComponent(location.hash.slice(9)));
  const i = r && r.querySelector('figure img');
  if (i) { r.hidden = false; open(r, i); }
}
)JS";

constexpr const char* kStyle = R"CSS(
body{font-family:system-ui,sans-serif;margin:24px;background:#f6f7f9;color:#1d2330}
table{border-collapse:collapse;width:100%;background:#fff}td,th{border:1px solid #d8dce3;padding:6px;vertical-align:top;font-size:13px}
th{background:#eef1f6;text-align:left}.pass{color:#137333;font-weight:600}.fail{color:#b3261e;font-weight:600}.skip{color:#8a6d00}
tr.case[data-status=fail]{background:#fff5f4}
img{image-rendering:pixelated;width:128px;height:auto;border:1px solid #ccc;background:#222;cursor:zoom-in}.checks div{margin:2px 0}
td.imgs{white-space:nowrap}figure{display:inline-block;margin:0 6px 0 0;text-align:center}figcaption{font-size:11px;color:#555}
#failed{background:#fff;border:1px solid #f0b8b3;padding:8px 12px;margin:8px 0}#failed a{margin-right:12px;color:#b3261e}
.controls{margin:10px 0}.controls button,#zoom button{font:inherit;padding:3px 10px;border:1px solid #aab;background:#fff;border-radius:4px;cursor:pointer}
.controls button.on,#zoom button.on{background:#1d2330;color:#fff}
.legend{font-size:12px;color:#444}.ramp{display:inline-block;width:160px;height:10px;vertical-align:middle;border:1px solid #999;
background:linear-gradient(90deg,#000 0%,#00f 33%,#f00 66%,#ff0 90%,#fff 100%)}
#zoom{position:fixed;inset:0;background:rgba(10,12,18,.98);color:#eee;display:flex;flex-direction:column}
#zoom[hidden]{display:none}#zoom .bar{padding:8px 12px;display:flex;gap:8px;align-items:center;flex-wrap:wrap}
#zoom .view{flex:1;overflow:auto;padding:12px}#zoom img{width:auto;cursor:crosshair;border:none}
)CSS";

// The folder's parent name: "presets/aa/msaa" -> "aa" (the family, for the filter).
std::string family_of(const std::string& where) {
    fs::path p = fs::path(where).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
    return p.parent_path().filename().string();
}

// The report's entries in reading order: failures first, then skipped cases, then passes; the
// run's order within each.
std::vector<const ReportEntry*> failures_first(const std::vector<ReportEntry>& entries) {
    std::vector<const ReportEntry*> out;
    for (const auto& e : entries) out.push_back(&e);
    auto rank = [](const ReportEntry* e) { return e->result.skipped ? 1 : e->result.passed ? 2 : 0; };
    std::stable_sort(out.begin(), out.end(), [&](const ReportEntry* a, const ReportEntry* b) { return rank(a) < rank(b); });
    return out;
}

// Failures only: the images this run wrote into the report folder for cases not listed go again
// (only those files, and folders they leave empty), so a green run's report is a page, not the
// whole catalogue's renders.
void remove_unlisted_images(const fs::path& dir, const std::vector<ReportEntry>& entries) {
    std::error_code ec;
    const fs::path canon_dir = fs::weakly_canonical(dir, ec);
    auto remove = [&](const std::string& file) {
        if (file.empty()) return;
        fs::path f = fs::weakly_canonical(file, ec);
        fs::path rel = f.lexically_relative(canon_dir);
        if (rel.empty() || *rel.begin() == "..") return;  // not ours to delete (a golden in the preset)
        fs::remove(f, ec);
        for (fs::path d = f.parent_path(); d != canon_dir && d.string().size() > canon_dir.string().size(); d = d.parent_path())
            if (!fs::remove(d, ec)) break;  // stops at the first folder that is not empty
    };
    for (const auto& e : entries) {
        if (!e.result.passed) continue;
        remove(e.result.image_file);
        for (const auto& c : e.result.checks)
            for (const auto* f : {&c.actual_file, &c.expected_file, &c.diff_file}) remove(*f);
    }
}

} // namespace

Status write_report(const fs::path& dir, const std::vector<ReportEntry>& entries, const std::string& device, double total_ms,
                    bool failures_only) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    int passed = 0, failed = 0, skipped = 0;
    for (const auto& e : entries) (e.result.skipped ? skipped : e.result.passed ? passed : failed)++;
    if (failures_only) remove_unlisted_images(dir, entries);
    std::vector<const ReportEntry*> shown;
    for (const ReportEntry* e : failures_first(entries))
        if (!failures_only || !e->result.passed) shown.push_back(e);
    auto id_of = [](const ReportEntry& e) { return (safe_relative(e.where) / e.result.name).generic_string(); };

    std::ofstream h(dir / "index.html");
    h << "<!doctype html><html><head><meta charset=\"utf-8\"><title>passlab test report</title><style>" << kStyle
      << "</style></head><body data-default-show=\"" << (failed ? "failed" : "all") << "\">\n";
    h << "<h1>passlab test report</h1><p><b>" << passed << " passed, " << failed << " failed"
      << (skipped ? ", " + std::to_string(skipped) + " skipped" : "") << "</b> &middot; " << html_escape(device)
      << " &middot; " << static_cast<long>(total_ms) << " ms"
      << (failures_only ? " &middot; failures only: the " + std::to_string(passed) + " passing cases are counted, not listed" : "")
      << "</p>\n";
    if (failed) {
        h << "<div id=\"failed\"><b>Failed:</b> ";
        for (const ReportEntry* e : shown)
            if (!e->result.passed && !e->result.skipped)
                h << "<a href=\"#" << html_escape(id_of(*e)) << "\">" << html_escape(e->where) << ": " << html_escape(e->result.name) << "</a>";
        h << "</div>\n";
    }
    std::vector<std::string> families;
    for (const ReportEntry* e : shown)
        if (auto f = family_of(e->where); std::find(families.begin(), families.end(), f) == families.end()) families.push_back(f);
    std::sort(families.begin(), families.end());
    h << "<div class=\"controls\">show <button data-show=\"failed\">failed (" << failed << ")</button> <button data-show=\"all\">all ("
      << shown.size() << ")</button> &nbsp; family <select id=\"family\"><option value=\"\">every family</option>";
    for (const auto& f : families) h << "<option>" << html_escape(f) << "</option>";
    h << "</select> &nbsp; <span id=\"shown\"></span></div>\n";
    h << "<p class=\"legend\">Click an image to inspect it: zoom to single texels, switch rendered / golden / diff, space flips "
         "rendered and golden. Diff: the largest |rendered &minus; golden| of R, G, B per pixel, <span class=\"ramp\"></span> "
         "0 (black) &rarr; blue &rarr; red &rarr; yellow &rarr; 0.25 and more (white).</p>\n";
    h << "<table><tr><th>preset</th><th>case</th><th>result</th><th>images</th><th>checks (measured vs tolerance)</th><th>ms</th></tr>\n";
    for (const ReportEntry* ep : shown) {
        const auto& e = *ep;
        const auto& r = e.result;
        const std::string id = id_of(e);
        std::string cls = r.skipped ? "skip" : r.passed ? "pass" : "fail";
        h << "<tr class=\"case\" id=\"" << html_escape(id) << "\" data-status=\"" << cls << "\" data-family=\"" << html_escape(family_of(e.where))
          << "\" data-title=\"" << html_escape(e.where + ": " + r.name) << "\"><td>" << html_escape(e.where) << "</td><td>" << html_escape(r.name)
          << "</td><td class=\"" << cls << "\">" << (r.skipped ? "SKIP" : r.passed ? "PASS" : "FAIL") << "</td><td class=\"imgs\">";
        auto figure = [&](const std::string& src, const char* label) {
            h << "<figure><img src=\"" << html_escape(src) << "\" data-label=\"" << label << "\" alt=\"" << label << "\"><figcaption>" << label
              << "</figcaption></figure>";
        };
        if (auto img = local_copy(dir, r.image_file, id + ".png"); !img.empty()) figure(img, "rendered");
        for (const auto& c : r.checks) {
            if (auto f = local_copy(dir, c.expected_file, id + ".expected" + fs::path(c.expected_file).extension().string()); !f.empty() && fs::path(f).extension() == ".png")
                figure(f, "golden");
            if (auto f = local_copy(dir, c.diff_file, id + ".diff.png"); !f.empty()) figure(f, "diff");
        }
        // What each failed check read (another pass, level or layer; tone-mapped when HDR).
        for (size_t k = 0; k < r.checks.size(); ++k) {
            const auto& c = r.checks[k];
            if (c.passed || !c.expected_file.empty() || c.actual_file.empty()) continue;
            const std::string ext = fs::path(c.actual_file).filename().string().find(".tonemapped.") != std::string::npos ? ".tonemapped.png" : ".png";
            if (auto f = local_copy(dir, c.actual_file, id + ".check-" + std::to_string(k + 1) + ext); !f.empty())
                figure(f, ext == ".png" ? "check read" : "check read (tone-mapped)");
        }
        h << "</td><td class=\"checks\">";
        if (r.skipped) h << html_escape(r.skip_reason);
        if (!r.error.empty()) h << "<pre>" << html_escape(r.error) << "</pre>";
        for (const auto& c : r.checks)
            h << "<div><span class=\"" << (c.passed ? "pass" : "fail") << "\">" << (c.passed ? "ok" : "FAIL") << "</span> "
              << html_escape(c.what) << ": " << html_escape(c.detail) << "</div>";
        for (const auto& v : r.validation) h << "<div class=\"fail\">validation: " << html_escape(v) << "</div>";
        h << "</td><td>" << static_cast<long>(r.ms) << "</td></tr>\n";
    }
    h << "</table>\n<div id=\"zoom\" hidden><div class=\"bar\"><b id=\"ztitle\"></b><span id=\"zviews\"></span>"
         "<button id=\"zflip\">flip rendered/golden (space)</button><button id=\"zout\">&minus;</button><button id=\"zin\">+</button>"
         "<span id=\"zinfo\"></span><button id=\"zclose\">close (Esc)</button></div><div class=\"view\"><img id=\"zimg\" alt=\"\"></div></div>\n"
      << "<script>" << kScript << "</script></body></html>\n";
    h.close();
    if (!h) {
        Error err = make_error("cannot write " + (dir / "index.html").string());
        err.code = ExitCode::environment;
        return err;
    }
    return ok_status();
}

} // namespace pl::lab
