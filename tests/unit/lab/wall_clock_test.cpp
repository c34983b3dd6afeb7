// Clock params in `run`: the local date in either month convention; a --set pins it; other
// params are left alone.
#include "wall_clock.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

namespace pl::lab {
namespace {

graph::ParamDesc param(const std::string& name, const std::string& clock) {
    graph::ParamDesc p;
    p.name = name;
    p.type = graph::ParamType::vec4;
    p.value = {2026, 0, 1, 43200};
    p.clock = clock;
    return p;
}

TEST(WallClock, LocalDateInBothConventions) {
    setenv("TZ", "UTC", 1);
    tzset();
    // 2025-07-04 13:45:30 UTC
    const std::time_t t = 1751636730;
    std::vector<graph::ParamDesc> ps = {param("date", "date"), param("isf", "date-month1"), param("plain", "")};
    EXPECT_EQ(apply_wall_clock(ps, {}, t), 2);
    EXPECT_EQ(ps[0].value, (std::array<double, 4>{2025, 6, 4, 13 * 3600 + 45 * 60 + 30}));
    EXPECT_EQ(ps[1].value, (std::array<double, 4>{2025, 7, 4, 13 * 3600 + 45 * 60 + 30}));
    EXPECT_EQ(ps[2].value, (std::array<double, 4>{2026, 0, 1, 43200}));
}

TEST(WallClock, CommandLinePins) {
    std::vector<graph::ParamDesc> ps = {param("date", "date")};
    EXPECT_EQ(apply_wall_clock(ps, {"date=2020,1,2,3"}, 1751636730), 0);
    EXPECT_EQ(ps[0].value, (std::array<double, 4>{2026, 0, 1, 43200}));
}

} // namespace
} // namespace pl::lab
