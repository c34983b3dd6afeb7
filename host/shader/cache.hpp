// SPIR-V cache keyed by a content hash of the fully expanded sources (see cache.cpp).
#pragma once

#include "shader/program.hpp"

#include <optional>

namespace pl::shader {

std::optional<std::vector<StageSpirv>> cache_load(const std::filesystem::path& dir, const std::string& key_text);
void cache_store(const std::filesystem::path& dir, const std::string& key_text, const std::vector<StageSpirv>& stages);

} // namespace pl::shader
