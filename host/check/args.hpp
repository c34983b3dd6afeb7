// Typed access to a check's free-form arguments (from the [[test]] TOML).
#pragma once

#include "graph/desc.hpp"

#include <map>
#include <string>
#include <vector>

namespace pl::check {

using Args = std::map<std::string, graph::Value>;

double num(const Args& a, const std::string& k, double def);
std::vector<double> vec(const Args& a, const std::string& k);
std::string str(const Args& a, const std::string& k, const std::string& def = "");
// `channel = 0` or `channels = [0, 1, 2]`; default RGB.
std::vector<int> channels(const Args& a);
std::string fmt(double v);

} // namespace pl::check
