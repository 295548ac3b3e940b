// A small command-line reader for the subcommands: positional arguments and
// `--flag VALUE` / `--flag=VALUE` / boolean `--flag`. Unknown flags, missing values
// and malformed numbers are reported, never guessed.
#pragma once
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gridcull {

class CliArgs {
public:
    // value_flags take a value; switch_flags take none. Names without the dashes.
    CliArgs(std::set<std::string> value_flags, std::set<std::string> switch_flags);
    // Reads argv[first..argc). Returns false and sets error() on the first problem.
    bool parse(int argc, char** argv, int first);
    const std::string& error() const { return error_; }

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(const std::string& flag) const;
    std::string text(const std::string& flag, const std::string& fallback) const;
    // Integer flag within [lo, hi]; returns false and sets error() if malformed.
    bool integer(const std::string& flag, long long lo, long long hi, long long& value);
    // Finite number flag within [lo, hi]; returns false and sets error() if malformed.
    bool number(const std::string& flag, double lo, double hi, double& value);

private:
    std::set<std::string> value_flags_;
    std::set<std::string> switch_flags_;
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
    std::string error_;
};

}  // namespace gridcull
