// "Copy as --set" must produce a command that runs as pasted: each word survives a POSIX shell.
#include "command_line.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

using namespace pl::lab;

namespace {

// What /bin/sh makes of `line` after "printf '%s\n'": one output line per word.
std::string words_through_shell(const std::string& line) {
    std::string cmd = "printf '%s\\n' " + line;
    FILE* f = popen(cmd.c_str(), "r");
    if (!f) return "<popen failed>";
    std::string out;
    std::array<char, 256> buf{};
    while (fgets(buf.data(), buf.size(), f)) out += buf.data();
    pclose(f);
    return out;
}

} // namespace

TEST(CommandLine, SafeWordsStayAsTheyAre) {
    EXPECT_EQ(shell_quote("octaves=3"), "octaves=3");
    EXPECT_EQ(shell_quote("/work/presets/procedural/fbm"), "/work/presets/procedural/fbm");
    EXPECT_EQ(shell_quote("tint=0.5,0.25,1"), "tint=0.5,0.25,1");
}

TEST(CommandLine, EveryWordSurvivesTheShell) {
    const std::string odd = "my presets/it's $HOME `x` *; \"q\"";
    EXPECT_EQ(words_through_shell(shell_quote(odd)), odd + "\n");
    EXPECT_EQ(words_through_shell(shell_quote("")), "\n");
    const std::string cmd = render_command("/opt/pass lab/passlab", "/home/me/my fbm", {"gain=0.5", "mode=ridged"});
    EXPECT_EQ(cmd, "'/opt/pass lab/passlab' render '/home/me/my fbm' --set gain=0.5 --set mode=ridged");
    EXPECT_EQ(words_through_shell(cmd), "/opt/pass lab/passlab\nrender\n/home/me/my fbm\n--set\ngain=0.5\n--set\nmode=ridged\n");
}
