#include "app/cli_args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace gridcull {

CliArgs::CliArgs(std::set<std::string> value_flags, std::set<std::string> switch_flags)
    : value_flags_(std::move(value_flags)), switch_flags_(std::move(switch_flags)) {}

bool CliArgs::parse(int argc, char** argv, int first) {
    for (int i = first; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg.size() < 2 || arg.compare(0, 2, "--") != 0 || arg == "--") {
            if (arg == "-h") {
                values_["help"] = "";
                continue;
            }
            if (!arg.empty() && arg[0] == '-' && arg != "-") {
                error_ = "unknown option '" + arg + "'";
                return false;
            }
            positional_.push_back(arg);
            continue;
        }
        std::string name = arg.substr(2);
        std::optional<std::string> inline_value;
        if (const auto eq = name.find('='); eq != std::string::npos) {
            inline_value = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        if (switch_flags_.count(name)) {
            if (inline_value) {
                error_ = "option --" + name + " takes no value";
                return false;
            }
            values_[name] = "";
        } else if (value_flags_.count(name)) {
            if (inline_value) {
                values_[name] = *inline_value;
            } else if (i + 1 < argc) {
                values_[name] = argv[++i];
            } else {
                error_ = "option --" + name + " needs a value";
                return false;
            }
        } else {
            error_ = "unknown option '--" + name + "'";
            return false;
        }
    }
    return true;
}

bool CliArgs::has(const std::string& flag) const {
    return values_.count(flag) != 0;
}

std::string CliArgs::text(const std::string& flag, const std::string& fallback) const {
    const auto it = values_.find(flag);
    return it == values_.end() ? fallback : it->second;
}

bool CliArgs::integer(const std::string& flag, long long lo, long long hi, long long& value) {
    const auto it = values_.find(flag);
    if (it == values_.end()) return true;  // keep the caller's default
    const std::string& s = it->second;
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (s.empty() || *end != '\0' || errno == ERANGE || v < lo || v > hi) {
        error_ = "option --" + flag + ": expected an integer from " + std::to_string(lo) + " to " +
                 std::to_string(hi) + ", got '" + s + "'";
        return false;
    }
    value = v;
    return true;
}

bool CliArgs::number(const std::string& flag, double lo, double hi, double& value) {
    const auto it = values_.find(flag);
    if (it == values_.end()) return true;  // keep the caller's default
    const std::string& s = it->second;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v) || v < lo || v > hi) {
        error_ = "option --" + flag + ": expected a number from " + std::to_string(lo) + " to " +
                 std::to_string(hi) + ", got '" + s + "'";
        return false;
    }
    value = v;
    return true;
}

}  // namespace gridcull
