#include "command_line.hpp"

#include <filesystem>
#include <system_error>

namespace pl::lab {

std::string shell_quote(const std::string& word) {
    static const std::string safe = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=.,/:@%";
    if (!word.empty() && word.find_first_not_of(safe) == std::string::npos) return word;
    std::string out = "'";
    for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string render_command(const std::string& exe, const std::string& preset_dir, const std::vector<std::string>& sets) {
    std::string out = shell_quote(exe) + " render " + shell_quote(preset_dir);
    for (const auto& s : sets) out += " --set " + shell_quote(s);
    return out;
}

std::string self_executable() {
    std::error_code ec;
    auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("passlab") : p.string();
}

} // namespace pl::lab
