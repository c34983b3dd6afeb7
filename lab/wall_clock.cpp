#include "wall_clock.hpp"

#include "exec/params.hpp"

namespace pl::lab {

int apply_wall_clock(std::vector<graph::ParamDesc>& params, const std::vector<std::string>& cli_sets, std::time_t start) {
    std::tm t{};
    if (!localtime_r(&start, &t)) return 0;
    int n = 0;
    for (auto& p : params) {
        if (p.clock.empty()) continue;
        if (exec::assigns(cli_sets, p.name)) continue;  // the user pinned it
        const double month = t.tm_mon + (p.clock == "date-month1" ? 1 : 0);
        p.value = {1900.0 + t.tm_year, month, double(t.tm_mday), t.tm_hour * 3600.0 + t.tm_min * 60.0 + t.tm_sec};
        ++n;
    }
    return n;
}

} // namespace pl::lab
