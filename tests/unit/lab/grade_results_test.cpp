// The grade a platform reads: scores by weight, skipped cases counted neither way, hidden cases
// graded without their figures in passlab's JSON but with them (and their visibility) in
// Gradescope's, and an ungradable submission scoring 0 on every declared case.
#include "grade_results.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace pl::lab {
namespace {

check::CaseResult make_case(const std::string& name, bool passed, double weight = 1.0,
                            const std::string& visibility = "visible") {
    check::CaseResult r;
    r.name = name;
    r.passed = passed;
    r.weight = weight;
    r.visibility = visibility;
    r.hint = "look at TODO 2";
    check::CheckResult ch;
    ch.what = "probe uv=(0.5,0.5)";
    ch.passed = passed;
    ch.detail = "got 0.25, expected 0.5 +- 0.01";
    r.checks.push_back(ch);
    return r;
}

GradeSummary sample() {
    GradeSummary s;
    s.preset = "shading/lambert";
    s.exercise = "mine";
    s.device = "llvmpipe";
    s.cases = {make_case("furnace", true, 2.0), make_case("cosine", false), make_case("secret", false, 3.0, "hidden")};
    check::CaseResult skipped = make_case("needs-feature", false);
    skipped.skipped = true;
    skipped.skip_reason = "device lacks fragmentShaderInterlock";
    s.cases.push_back(skipped);
    return s;
}

TEST(GradeResults, ScoresByWeightAndSkipsCountNeitherWay) {
    Score sc = score_of(sample());
    EXPECT_DOUBLE_EQ(sc.score, 2.0);
    EXPECT_DOUBLE_EQ(sc.max_score, 6.0);
    EXPECT_EQ(sc.passed, 1);
    EXPECT_EQ(sc.failed, 2);
    EXPECT_EQ(sc.skipped, 1);
}

TEST(GradeResults, PasslabJsonHidesTheFiguresOfHiddenCases) {
    auto j = grade_json(sample());
    EXPECT_EQ(j["score"], 2.0);
    EXPECT_EQ(j["max_score"], 6.0);
    EXPECT_EQ(j["graded"], true);
    ASSERT_EQ(j["cases"].size(), 4u);
    const auto& cosine = j["cases"][1];
    EXPECT_EQ(cosine["status"], "failed");
    EXPECT_EQ(cosine["hint"], "look at TODO 2");
    EXPECT_EQ(cosine["checks"][0]["detail"], "got 0.25, expected 0.5 +- 0.01");
    EXPECT_FALSE(j["cases"][0].contains("hint")) << "a passed case needs no hint";
    const auto& secret = j["cases"][2];
    EXPECT_EQ(secret["status"], "failed");
    EXPECT_EQ(secret["max_score"], 3.0);
    EXPECT_EQ(secret["visibility"], "hidden");
    EXPECT_FALSE(secret.contains("checks"));
    EXPECT_FALSE(secret.contains("hint"));
    EXPECT_EQ(j["cases"][3]["status"], "skipped");
    EXPECT_EQ(j["cases"][3]["max_score"], 0.0);
}

TEST(GradeResults, GradescopeSchema) {
    auto j = gradescope_json(sample());
    EXPECT_EQ(j["score"], 2.0);
    ASSERT_TRUE(j["execution_time"].is_number_integer());
    ASSERT_TRUE(j["output"].is_string());
    EXPECT_NE(j["output"].get<std::string>().find("score 2 of 6"), std::string::npos) << j["output"];
    ASSERT_EQ(j["tests"].size(), 4u);
    for (const auto& t : j["tests"]) {
        for (const char* k : {"name", "score", "max_score", "visibility"}) EXPECT_TRUE(t.contains(k)) << k;
        EXPECT_LE(t["score"].get<double>(), t["max_score"].get<double>());
    }
    EXPECT_EQ(j["tests"][0]["status"], "passed");
    EXPECT_EQ(j["tests"][1]["status"], "failed");
    // Gradescope withholds hidden output itself, so the instructor's view keeps the figures.
    EXPECT_EQ(j["tests"][2]["visibility"], "hidden");
    EXPECT_NE(j["tests"][2]["output"].get<std::string>().find("got 0.25"), std::string::npos);
    EXPECT_NE(j["tests"][2]["output"].get<std::string>().find("hint: look at TODO 2"), std::string::npos);
    EXPECT_FALSE(j["tests"][3].contains("status")) << "a skipped case did not pass";
    EXPECT_NE(j["tests"][3]["output"].get<std::string>().find("not graded"), std::string::npos);
}

TEST(GradeResults, AnUngradableSubmissionScoresZeroOnEveryCase) {
    GradeSummary s = sample();
    for (auto& c : s.cases) c.passed = true;  // as declared_cases leaves them is false; be strict anyway
    s.not_graded = "your files do not build yet:\nlambert.frag:12:5: error: ...";
    Score sc = score_of(s);
    EXPECT_DOUBLE_EQ(sc.score, 0.0);
    auto g = gradescope_json(s);
    EXPECT_EQ(g["score"], 0.0);
    EXPECT_NE(g["tests"][0]["output"].get<std::string>().find("lambert.frag:12:5"), std::string::npos);
    auto j = grade_json(s);
    EXPECT_EQ(j["graded"], false);
    EXPECT_EQ(j["cases"][0]["status"], "failed");
}

} // namespace
} // namespace pl::lab
