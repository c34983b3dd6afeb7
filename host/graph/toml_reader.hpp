// Typed, located access to a toml++ table: every value read keeps its file:line:col, unknown
// keys are errors with a "did you mean", wrong types name the expected type.
#pragma once

#include "graph/desc.hpp"

#include <toml++/toml.h>

#include <set>

namespace pl::graph {

class TableReader {
  public:
    TableReader(const toml::table& t, std::string file, std::string what)
        : t_(t), file_(std::move(file)), what_(std::move(what)) {}

    SourceLoc loc_of(const toml::node& n) const;
    SourceLoc loc() const { return loc_of(t_); }
    SourceLoc key_loc(const std::string& key) const;
    const toml::node* get(const std::string& key);  // marks the key as known
    bool has(const std::string& key) const { return t_.contains(key); }

    Status str(const std::string& key, std::string& out, SourceLoc* where = nullptr);
    Status boolean(const std::string& key, bool& out);
    Status number(const std::string& key, double& out);
    Status integer(const std::string& key, int& out);
    Status floats(const std::string& key, float& out);
    Status numbers(const std::string& key, std::vector<double>& out, size_t min_n, size_t max_n);
    Status strings(const std::string& key, std::vector<std::string>& out);
    Status size(const std::string& key, SizeExpr& out);
    // One of `allowed`, with a suggestion otherwise.
    Status choice(const std::string& key, std::string& out, const std::vector<std::string>& allowed);

    // Errors for every key not read and not in `also_allowed`.
    Status finish(const std::vector<std::string>& also_allowed = {});

    Error error(const std::string& msg, const SourceLoc& l) const;
    Error type_error(const std::string& key, const std::string& expected) const;
    const toml::table& table() const { return t_; }
    const std::string& file() const { return file_; }

  private:
    const toml::table& t_;
    std::string file_, what_;
    std::set<std::string> known_;
};

Status read_size_node(const toml::node& n, const TableReader& r, SizeExpr& out);
Value to_value(const toml::node& n);

} // namespace pl::graph
