// The command line behind the panel's "Copy as --set": it must run as pasted, in any shell
// folder, so it names this passlab executable and the preset folder by absolute path and
// quotes every word a POSIX shell would split or expand.
#pragma once

#include <string>
#include <vector>

namespace pl::lab {

// `word` as one POSIX shell word: unchanged when it holds only safe characters, else in single
// quotes (a quote inside becomes '\'' ).
std::string shell_quote(const std::string& word);

// "EXE render PRESET_DIR --set a=1 ..." with every word quoted.
std::string render_command(const std::string& exe, const std::string& preset_dir, const std::vector<std::string>& sets);

// This process's executable (/proc/self/exe), else "passlab".
std::string self_executable();

} // namespace pl::lab
