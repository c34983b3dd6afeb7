// lab/ pieces that need no device: event lines, --json round trip (how -j workers report),
// JUnit XML, case selection and sharding.
#include "events.hpp"
#include "results.hpp"
#include "test_select.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace pl::lab;

namespace {

std::string slurp(const fs::path& f) {
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

fs::path scratch(const std::string& name) {
    fs::path d = fs::temp_directory_path() / ("passlab-lab-test-" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

RunSummary sample() {
    RunSummary s;
    s.device = "lavapipe";
    s.ms = 1234;
    ReportEntry a{"presets/aa/msaa", {}};
    a.result.name = "edge-coverage";
    a.result.passed = false;
    a.result.ms = 12;
    pl::check::CheckResult c;
    c.what = "golden snapshots/x.png";
    c.detail = "rmse 0.5 (≤ 0.01) <&> \x01 ok";
    c.actual_file = "/tmp/a.png";
    c.diff_file = "/tmp/d.png";
    a.result.checks.push_back(c);
    ReportEntry b{"tests/graphs/msaa", {}};
    b.result.name = "edge-coverage";
    b.result.passed = true;
    pl::check::CheckResult w;
    w.what = "golden g.png";
    w.passed = true;
    w.golden_write = pl::check::CheckResult::GoldenWrite::written;
    b.result.checks.push_back(w);
    ReportEntry k{"tests/graphs/msaa", {}};
    k.result.name = "needs-feature";
    k.result.skipped = true;
    k.result.skip_reason = "device lacks geometryShader";
    s.entries = {a, b, k};
    return s;
}

} // namespace

TEST(EventLog, EscapesControlCharactersInsteadOfReplacingThem) {
    fs::path f = scratch("events") / "e.jsonl";
    {
        EventLog log(f.string());
        log.write("reload-failed", {{"message", std::string("line one\nline\ttwo \x01 \"q\"")}, {"line", 6}});
    }
    std::string line = slurp(f);
    ASSERT_EQ(line.back(), '\n');
    EXPECT_EQ(line.find('\n'), line.size() - 1) << "one event per line";
    EXPECT_NE(line.find("\\u0001"), std::string::npos) << line;
    EXPECT_NE(line.find("\\t"), std::string::npos);
    EXPECT_EQ(line.rfind("{\"event\":\"reload-failed\",\"t_ms\":", 0), 0u) << "event first: " << line;
    auto j = nlohmann::json::parse(line);
    EXPECT_EQ(j["message"], "line one\nline\ttwo \x01 \"q\"");
    EXPECT_EQ(j["line"], 6);
}

TEST(Results, JsonRoundTripKeepsEveryField) {
    RunSummary s = sample();
    auto back = run_summary_from_json(nlohmann::ordered_json::parse(to_json(s).dump()));
    ASSERT_TRUE(back);
    ASSERT_EQ(back->entries.size(), 3u);
    EXPECT_EQ(back->entries[0].where, "presets/aa/msaa");
    EXPECT_FALSE(back->entries[0].result.passed);
    EXPECT_EQ(back->entries[0].result.checks[0].detail, s.entries[0].result.checks[0].detail);
    EXPECT_EQ(back->entries[0].result.checks[0].diff_file, "/tmp/d.png");
    EXPECT_EQ(back->entries[1].result.checks[0].golden_write, pl::check::CheckResult::GoldenWrite::written);
    EXPECT_TRUE(back->entries[2].result.skipped);
    Counts n = count(back->entries);
    EXPECT_EQ(n.passed, 1);
    EXPECT_EQ(n.failed, 1);
    EXPECT_EQ(n.skipped, 1);
    EXPECT_EQ(n.goldens_written, 1);
    EXPECT_FALSE(run_summary_from_json(nlohmann::ordered_json::parse("{\"cases\": [{\"name\": 1}]}")));
}

TEST(Results, JunitHasOneTestcasePerCaseFiguresAndAttachments) {
    fs::path f = scratch("junit") / "r.xml";
    ASSERT_TRUE(write_junit(f, sample()));
    std::string x = slurp(f);
    EXPECT_NE(x.find("<testsuites name=\"passlab\" tests=\"3\" failures=\"1\" skipped=\"1\""), std::string::npos) << x;
    EXPECT_NE(x.find("<testsuite name=\"presets/aa/msaa\""), std::string::npos);
    EXPECT_NE(x.find("<testsuite name=\"tests/graphs/msaa\" tests=\"2\""), std::string::npos);
    EXPECT_NE(x.find("<failure message=\"golden snapshots/x.png: rmse 0.5 (≤ 0.01) &lt;&amp;&gt; \xEF\xBF\xBD ok\""), std::string::npos) << x;
    EXPECT_NE(x.find("[[ATTACHMENT|/tmp/a.png]]"), std::string::npos);
    EXPECT_NE(x.find("[[ATTACHMENT|/tmp/d.png]]"), std::string::npos);
    EXPECT_NE(x.find("<skipped message=\"device lacks geometryShader\"/>"), std::string::npos);
    EXPECT_EQ(x.find('\x01'), std::string::npos) << "no control character is valid XML 1.0";
}

TEST(Results, WriteErrorsAreEnvironmentErrors) {
    auto s = write_junit("/proc/passlab-no/r.xml", sample());
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().code, pl::ExitCode::environment);
}

TEST(Select, ShardSpecs) {
    EXPECT_TRUE(parse_shard("1/1"));
    auto s = parse_shard("2/4");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->index, 1);
    EXPECT_EQ(s->total, 4);
    for (const char* bad : {"0/2", "3/2", "2", "1/0", "a/b", "1/2x"}) {
        auto b = parse_shard(bad);
        ASSERT_FALSE(b) << bad;
        EXPECT_EQ(b.error().code, pl::ExitCode::usage);
    }
}

TEST(Select, ShardsPartitionTheCases) {
    std::vector<TestUnit> all(2);
    all[0].all_cases = {"a", "b", "c"};
    all[1].all_cases = {"d", "e"};
    std::multiset<std::string> seen;
    for (int k = 0; k < 3; ++k) {
        auto units = all;
        select_shard(units, {k, 3});
        for (const auto& u : units) seen.insert(u.cases->begin(), u.cases->end());
        EXPECT_LE(selected_count(units), 2u);
    }
    EXPECT_EQ(seen, (std::multiset<std::string>{"a", "b", "c", "d", "e"})) << "every case in exactly one shard";
}

TEST(Select, CaseNamesAndGlobs) {
    std::vector<TestUnit> units(2);
    units[0].all_cases = {"default", "edge-coverage"};
    units[1].all_cases = {"edge-sharp"};
    auto typo = units;
    auto e = select_cases(typo, {"defualt"});
    ASSERT_FALSE(e);
    EXPECT_EQ(e.error().code, pl::ExitCode::usage);
    EXPECT_EQ(e.error().hint, "did you mean 'default'?");
    ASSERT_TRUE(select_cases(units, {"edge-*"}));
    EXPECT_EQ(*units[0].cases, (std::set<std::string>{"edge-coverage"}));
    EXPECT_EQ(*units[1].cases, (std::set<std::string>{"edge-sharp"}));
    auto none = units;
    ASSERT_TRUE(select_cases(none, {"zz*"}));
    EXPECT_EQ(selected_count(none), 0u) << "a glob matching nothing selects nothing (the verb then fails)";
}
