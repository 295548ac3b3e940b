// The `gridcull` command line: subcommands view, cull, bench, shot and knobs,
// parsed with CLI11 (app/cli_options.h binds the registry's knobs and the
// families' view flags to it). Every subcommand returns an exit status: 0 done,
// 2 bad command line, 3 scene rejected, 1 anything else.
#pragma once
#include <string>
#include <vector>

#include "culling/api/knobs.h"
#include "culling/scene/scene.h"

namespace gridcull {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;
constexpr int kExitSceneRejected = 3;

int runCli(int argc, char** argv);

// Loads a scene file; on failure prints every message to stderr and returns false.
bool loadSceneOrReport(const std::string& path, Scene& scene);

// Prints "gridcull CMD: message" and a pointer to --help; returns kExitUsage.
int usageError(const std::string& command, const std::string& message);

// Checks that every name in a comma-separated list is one of `known`.
bool splitAlgorithms(const std::string& list, std::vector<std::string>& names, std::string& error,
                     const std::vector<std::string>& known);

// One entry of bench's --algo list: NAME, or NAME:FLAG=VALUE[:FLAG=VALUE...] where
// each FLAG is a knob's flag without its dashes (oracle-res, ...; `gridcull knobs`
// lists them), set over the command's own knobs, so that one run can time the same
// algorithm at several settings side by side. `label` is the entry as written.
struct AlgoVariant {
    std::string label;
    std::string name;
    KnobValues knobs;
};
bool parseAlgoVariants(const std::string& list, const KnobValues& base,
                       std::vector<AlgoVariant>& variants, std::string& error);

// One line naming every knob's value, printed by bench so a table says what it
// measured: "oracle-res=1024 oracle-rays=16384 ...".
std::string describeKnobs(const KnobValues& knobs);

}  // namespace gridcull
