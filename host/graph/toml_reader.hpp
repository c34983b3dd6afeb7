// Typed, located access to one toml++ table. Every value read keeps its file:line:col (and is
// recorded in a KeyLocs when one is given), unknown keys are errors with a "did you mean" from the
// keys this table accepts, and wrong types name the expected and the found type. The section
// parsers are written against this class so that no key can be read without being checked.
#pragma once

#include "graph/desc.hpp"

#include <toml++/toml.h>

#include <cstdint>
#include <set>

namespace pl::graph {

class TableReader {
  public:
    // `what` names the table in messages ("[view]", "image 'hdr'"); `locs` (optional) receives
    // the value location of every key read, under `prefix` + key.
    TableReader(const toml::table& t, std::string file, std::string what, KeyLocs* locs = nullptr,
                std::string prefix = {})
        : t_(t), file_(std::move(file)), what_(std::move(what)), locs_(locs), prefix_(std::move(prefix)) {}

    SourceLoc loc_of(const toml::node& n) const;
    SourceLoc loc() const { return loc_of(t_); }
    SourceLoc key_loc(const std::string& key) const;    // where the key is written
    SourceLoc value_loc(const std::string& key) const;  // where its value starts
    const toml::node* get(const std::string& key);      // marks the key as known
    // Whether the key is written; also marks it as a key this table accepts (only valid keys
    // are asked about), so that optional keys read under `if (has(...))` are not "unknown".
    bool has(const std::string& key) const {
        known_.insert(key);
        return t_.contains(key);
    }

    Status str(const std::string& key, std::string& out, SourceLoc* where = nullptr);
    Status boolean(const std::string& key, bool& out);
    // TOML has nan and inf. NaN is refused always (every range check passes it: all
    // comparisons with it are false), inf unless `allow_inf` (far = inf, an infinite projection).
    Status number(const std::string& key, double& out, bool allow_inf = false);
    Status floats(const std::string& key, float& out, bool allow_inf = false);
    // Integers within [lo, hi]; a float such as 2.0 is refused (it is a typo for a count).
    Status integer(const std::string& key, int& out, int64_t lo = INT32_MIN, int64_t hi = INT32_MAX);
    Status uinteger(const std::string& key, uint32_t& out, int64_t hi = UINT32_MAX);
    Status numbers(const std::string& key, std::vector<double>& out, size_t min_n, size_t max_n);  // finite
    Status integers(const std::string& key, std::vector<int64_t>& out, size_t min_n, size_t max_n);
    Status strings(const std::string& key, std::vector<std::string>& out);
    Status size(const std::string& key, SizeExpr& out);
    // One of `allowed`, with a suggestion otherwise.
    Status choice(const std::string& key, std::string& out, const std::vector<std::string>& allowed);
    // The key's value as a table (nullptr when absent); a type error when it is not one.
    Result<const toml::table*> table(const std::string& key, const std::string& expected = "a table");

    // Errors for every key not read and not in `also_allowed`.
    Status finish(const std::vector<std::string>& also_allowed = {});

    Error error(const std::string& msg, const SourceLoc& l) const;
    Error type_error(const std::string& key, const std::string& expected) const;
    const toml::table& tbl() const { return t_; }
    const std::string& file() const { return file_; }
    const std::string& what() const { return what_; }
    KeyLocs* locs() const { return locs_; }
    const std::string& prefix() const { return prefix_; }

  private:
    const toml::table& t_;
    std::string file_, what_;
    KeyLocs* locs_;
    std::string prefix_;
    mutable std::set<std::string> known_;
};

// "a string", "an integer", "a table" ... for messages.
std::string type_name(const toml::node& n);
// A size: integer, [w, h], [w, h, d], or an expression string.
Status read_size_node(const toml::node& n, const TableReader& r, SizeExpr& out);
// A generic value (test `set`, check arguments): number, bool, string or array of numbers.
Result<Value> to_value(const toml::node& n, const TableReader& r, const std::string& key);

} // namespace pl::graph
