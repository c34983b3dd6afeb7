// The section parsers of parse.cpp, one file per group of sections.
#pragma once

#include "graph/desc.hpp"

#include <toml++/toml.h>

namespace pl::graph {

Status parse_params(const toml::table& t, const std::string& file, GraphDesc& g);
Status parse_images(const toml::table& t, const std::string& file, GraphDesc& g);
Status parse_buffers(const toml::table& t, const std::string& file, GraphDesc& g);
Status parse_meshes(const toml::table& t, const std::string& file, GraphDesc& g);
Status parse_pass(const toml::table& t, const std::string& file, GraphDesc& g);
Status parse_test(const toml::table& t, const std::string& file, GraphDesc& g);

bool is_identifier(const std::string& s);

} // namespace pl::graph
