// Errors as values for everything that comes from user content (TOML, GLSL, image files, sizes,
// names). Impossible host states abort instead (see vk/check.hpp); this type never carries those.
#pragma once

#include <cstdlib>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace pl {

// Where in a user file something came from. line/col are 1-based; 0 means "unknown".
struct SourceLoc {
    std::string file;
    int line = 0;
    int col = 0;

    bool known() const { return !file.empty(); }
    // "file:line:col", "file:line" or "file" depending on what is known.
    std::string str() const;
};

// Process exit codes shared by every verb (see docs/cli.md).
enum class ExitCode : int { ok = 0, user = 1, usage = 2, environment = 3 };

struct Error {
    std::string message;      // what is wrong, one sentence
    SourceLoc loc;            // where, if it comes from a file
    std::string pass;         // the pass it concerns, if any
    std::string resource;     // the image/buffer/param it concerns, if any
    std::string source_line;  // the offending line of the file, printed with a caret
    std::string hint;         // e.g. "did you mean 'albedo'?"
    ExitCode code = ExitCode::user;
    std::vector<std::string> notes;  // extra lines (include chain, list of valid names ...)

    // Multi-line human format:
    //   file:line:col: error: message [pass 'x', resource 'y']
    //       offending line
    //       ^
    //   hint / notes
    std::string format() const;
};

// Builder helpers keep call sites short.
Error make_error(std::string message, SourceLoc loc = {});

// Reads line `line` (1-based) of `file`; empty if unavailable. Used to fill Error::source_line.
std::string read_source_line(const std::string& file, int line);

// Result<T>: a T or an Error. Minimal stand-in for std::expected (C++23).
template <class T> class [[nodiscard]] Result {
  public:
    Result(T value) : v_(std::move(value)) {}
    Result(Error error) : v_(std::move(error)) {}

    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<0>(v_); }
    const T& value() const& { return std::get<0>(v_); }
    T&& value() && { return std::get<0>(std::move(v_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const { return std::get<1>(v_); }
    Error& error() { return std::get<1>(v_); }

  private:
    std::variant<T, Error> v_;
};

// Result<void> equivalent.
struct Ok {};
using Status = Result<Ok>;
inline Status ok_status() { return Ok{}; }

// Levenshtein distance and nearest-name suggestion ("did you mean ...").
int edit_distance(const std::string& a, const std::string& b);
// Returns the closest candidate within a reasonable distance, or "" if none is close.
std::string nearest_name(const std::string& wanted, const std::vector<std::string>& candidates);
// Adds "did you mean 'x'?" (when one is close) and, when `label` is given, a note listing every
// candidate ("label: a, b, c", or `empty_note` when there are none).
void suggest(Error& e, const std::string& wanted, const std::vector<std::string>& candidates,
             const std::string& label = {}, const std::string& empty_note = {}, char quote = '\'');

} // namespace pl
