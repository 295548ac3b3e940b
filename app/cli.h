// The `gridcull` command line (shared/spec/cli.md). Every subcommand returns an
// exit status: 0 done, 2 bad command line, 3 scene rejected, 1 anything else.
#pragma once
#include <set>
#include <string>

#include "culling/api/culler.h"
#include "culling/scene/scene.h"

namespace gridcull {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;
constexpr int kExitSceneRejected = 3;

int runCli(int argc, char** argv);

// Subcommands; argv[first] is the first argument after the command's name.
int runCullCommand(int argc, char** argv, int first);
int runBenchCommand(int argc, char** argv, int first);
int runShotCommand(int argc, char** argv, int first);
int runViewCommand(int argc, char** argv, int first);

// Loads a scene file; on failure prints every message to stderr and returns false.
bool loadSceneOrReport(const std::string& path, Scene& scene);

// Prints "gridcull CMD: message" and a pointer to --help; returns kExitUsage.
int usageError(const char* command, const std::string& message);

// The flags every culling command shares, and reading them into CullerOptions.
extern const char* const kCullerOptionsHelp;
class CliArgs;
bool readCullerOptions(CliArgs& args, CullerOptions& options);
// A command's own value flags plus every flag readCullerOptions reads.
std::set<std::string> withCullerOptionFlags(std::set<std::string> own);
// One line naming every option's value, printed by bench so a table says what it measured.
std::string describeCullerOptions(const CullerOptions& options);
// Checks that every name in a comma-separated list is one of `known` (default:
// cullerNames(), what the window offers; cull and bench also take appCullerNames()).
bool splitAlgorithms(const std::string& list, std::vector<std::string>& names, std::string& error,
                     const std::vector<std::string>& known = cullerNames());

// One entry of bench's --algo list: NAME, or NAME:FLAG=VALUE[:FLAG=VALUE...] where
// each FLAG is a culler option flag without its dashes (cell-size, lazy-prob, ...),
// applied over the command's own options, so that one run can time the same
// algorithm at several settings side by side. `label` is the entry as written.
struct AlgoVariant {
    std::string label;
    std::string name;
    CullerOptions options;
};
bool parseAlgoVariants(const std::string& list, const CullerOptions& base,
                       std::vector<AlgoVariant>& variants, std::string& error);

}  // namespace gridcull
