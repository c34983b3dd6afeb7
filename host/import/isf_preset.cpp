#include "import/import.hpp"

namespace pl::import {

Result<PresetFiles> import_isf(const std::filesystem::path& fs_file, const ImportOptions&) {
    return make_error("'" + fs_file.string() + "': ISF import is not implemented yet", {fs_file.string(), 1, 1});
}

} // namespace pl::import
