#include "report.hpp"

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

} // namespace

Status write_report(const fs::path& dir, const std::vector<ReportEntry>& entries, const std::string& device, double total_ms) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    int passed = 0, failed = 0, skipped = 0;
    for (const auto& e : entries) (e.result.skipped ? skipped : e.result.passed ? passed : failed)++;
    std::ofstream h(dir / "index.html");
    h << "<!doctype html><html><head><meta charset=\"utf-8\"><title>passlab test report</title><style>\n"
         "body{font-family:system-ui,sans-serif;margin:24px;background:#f6f7f9;color:#1d2330}\n"
         "table{border-collapse:collapse;width:100%;background:#fff}td,th{border:1px solid #d8dce3;padding:6px;vertical-align:top;font-size:13px}\n"
         "th{background:#eef1f6;text-align:left}.pass{color:#137333;font-weight:600}.fail{color:#b3261e;font-weight:600}.skip{color:#8a6d00}\n"
         "img{image-rendering:pixelated;width:128px;height:auto;border:1px solid #ccc;background:#222}.checks div{margin:2px 0}\n"
         "figure{display:inline-block;margin:0 6px 0 0;text-align:center}figcaption{font-size:11px;color:#555}</style></head><body>\n";
    h << "<h1>passlab test report</h1><p><b>" << passed << " passed, " << failed << " failed"
      << (skipped ? ", " + std::to_string(skipped) + " skipped" : "") << "</b> &middot; " << html_escape(device)
      << " &middot; " << static_cast<long>(total_ms) << " ms</p>\n";
    h << "<table><tr><th>preset</th><th>case</th><th>result</th><th>images</th><th>checks (measured vs tolerance)</th><th>ms</th></tr>\n";
    for (const auto& e : entries) {
        const auto& r = e.result;
        const std::string id = (safe_relative(e.where) / r.name).string();
        std::string cls = r.skipped ? "skip" : r.passed ? "pass" : "fail";
        h << "<tr><td>" << html_escape(e.where) << "</td><td>" << html_escape(r.name) << "</td><td class=\"" << cls << "\">"
          << (r.skipped ? "SKIP" : r.passed ? "PASS" : "FAIL") << "</td><td>";
        if (auto img = local_copy(dir, r.image_file, id + ".png"); !img.empty())
            h << "<figure><img src=\"" << img << "\"><figcaption>rendered</figcaption></figure>";
        for (const auto& c : r.checks) {
            if (auto f = local_copy(dir, c.expected_file, id + ".expected" + fs::path(c.expected_file).extension().string()); !f.empty() && fs::path(f).extension() == ".png")
                h << "<figure><img src=\"" << f << "\"><figcaption>golden</figcaption></figure>";
            if (auto f = local_copy(dir, c.diff_file, id + ".diff.png"); !f.empty())
                h << "<figure><img src=\"" << f << "\"><figcaption>diff</figcaption></figure>";
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
    h << "</table></body></html>\n";
    h.close();
    if (!h) {
        Error err = make_error("cannot write " + (dir / "index.html").string());
        err.code = ExitCode::environment;
        return err;
    }
    return ok_status();
}

} // namespace pl::lab
