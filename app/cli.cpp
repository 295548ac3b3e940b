#include "app/cli.h"

#include <cstdio>
#include <iostream>
#include <sstream>

#include "app/app_cullers.h"
#include "app/cli_commands.h"
#include "app/window.h"
#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"

namespace gridcull {

namespace {

const char* const kDescription =
    "gridcull: see occlusion culling work, frame by frame.\n"
    "With no command, opens the window on the built-in default scene.";

int dispatch(int argc, char** argv) {
    CLI::App app{kDescription, "gridcull"};
    app.formatter(helpFormatter());
    app.require_subcommand(0, 1);
    app.footer(
        "gridcull CMD --help: help for one command.\n"
        "exit status: 0 done, 2 bad command line, 3 scene rejected, 1 anything else.");
    bool version = false;
    app.add_flag("--version", version, "print the version and exit");
    CullCommand cull;
    BenchCommand bench;
    TradeCommand trade;
    WindowCommand shot, view;
    RecordCommand record;
    KnobsCommand knobs, counters;
    CLI::App* cull_app = addCullCommand(app, cull);
    CLI::App* bench_app = addBenchCommand(app, bench);
    CLI::App* trade_app = addTradeCommand(app, trade);
    CLI::App* shot_app = addShotCommand(app, shot);
    CLI::App* view_app = addViewCommand(app, view);
    CLI::App* record_app = addRecordCommand(app, record);
    CLI::App* knobs_app = addKnobsCommand(app, knobs);
    CLI::App* counters_app = addCountersCommand(app, counters);
    for (CLI::App* sub : app.get_subcommands({})) sub->formatter(helpFormatter());

    try {
        if (argc == 2 && std::string(argv[1]) == "help") throw CLI::CallForHelp();
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        // The help of the command asked about (CLI11 delegates to it).
        std::fputs(app.help().c_str(), stdout);
        return kExitOk;
    } catch (const CLI::ParseError& e) {
        std::string command = "";
        for (CLI::App* sub : app.get_subcommands({}))
            if (argc > 1 && sub->get_name() == argv[1]) command = sub->get_name();
        std::cerr << "gridcull" << (command.empty() ? "" : " " + command) << ": "
                  << parseErrorMessage(e) << "\n"
                  << "try 'gridcull" << (command.empty() ? "" : " " + command) << " --help'\n";
        return kExitUsage;
    }
    if (version) {
        std::printf("gridcull %s\n", GRIDCULL_VERSION);
        return kExitOk;
    }
    if (cull_app->parsed()) return runCull(cull);
    if (bench_app->parsed()) return runBench(bench);
    if (trade_app->parsed()) return runTrade(trade);
    if (shot_app->parsed()) return runShot(shot);
    if (view_app->parsed()) return runView(view);
    if (record_app->parsed()) return runRecord(record);
    if (knobs_app->parsed()) return runKnobs(knobs);
    if (counters_app->parsed()) return runCounters(counters);
    ViewOptions options;
    return runWindow(defaultScene(), options);
}

}  // namespace

bool splitAlgorithms(const std::string& list, std::vector<std::string>& names, std::string& error,
                     const std::vector<std::string>& known) {
    names.clear();
    std::stringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        bool found = false;
        for (const auto& k : known) found = found || k == name;
        if (!found) {
            std::string all;
            for (const auto& k : known) all += (all.empty() ? "" : ", ") + k;
            error = "unknown algorithm '" + name + "', expected one of: " + all;
            return false;
        }
        names.push_back(name);
    }
    if (names.empty()) {
        error = "--algo needs at least one algorithm name";
        return false;
    }
    return true;
}

bool parseAlgoVariants(const std::string& list, const KnobValues& base,
                       std::vector<AlgoVariant>& variants, std::string& error) {
    variants.clear();
    std::stringstream in(list);
    std::string entry;
    while (std::getline(in, entry, ',')) {
        std::vector<std::string> parts;
        std::stringstream fields(entry);
        std::string field;
        while (std::getline(fields, field, ':')) parts.push_back(field);
        if (parts.empty()) parts.push_back("");
        std::vector<std::string> names;
        if (!splitAlgorithms(parts[0], names, error, appAlgorithmNames())) return false;
        AlgoVariant variant{entry, parts[0], base};
        for (size_t i = 1; i < parts.size(); ++i) {
            const size_t eq = parts[i].find('=');
            if (eq == std::string::npos) {
                error = "--algo entry '" + entry + "': expected FLAG=VALUE after ':', got '" +
                        parts[i] + "'";
                return false;
            }
            const std::string flag = parts[i].substr(0, eq);
            const Knob* knob = findKnob(flag);
            if (!knob) {
                error = "--algo entry '" + entry + "': '" + flag +
                        "' is not a knob (gridcull knobs lists them)";
                return false;
            }
            // The reference's knobs go with any entry (they set what the image-space
            // families follow); another family's knob would do nothing here.
            const FamilyEntry* owner = familyOfKnob(flag);
            if (!owner->reference && owner != familyOfAlgorithm(registryAlgorithmOf(parts[0]))) {
                error = "--algo entry '" + entry + "': --" + flag + " is a knob of " +
                        owner->title + ", not of " + parts[0];
                return false;
            }
            double value = 0.0;
            if (!parseKnobValue(*knob, parts[i].substr(eq + 1), value, error)) {
                error = "--algo entry '" + entry + "': " + error;
                return false;
            }
            variant.knobs.set(flag, value);
        }
        variants.push_back(std::move(variant));
    }
    if (variants.empty()) {
        error = "--algo needs at least one algorithm name";
        return false;
    }
    return true;
}

std::string describeKnobs(const KnobValues& knobs) {
    std::string line;
    for (const Knob* knob : allKnobs())
        line +=
            (line.empty() ? "" : " ") + knob->flag + "=" + knobValueText(*knob, knobs.get(*knob));
    return line;
}

bool loadSceneOrReport(const std::string& path, Scene& scene) {
    SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.scene) {
        for (const auto& message : loaded.errors) std::cerr << message << "\n";
        if (loaded.errors.empty()) std::cerr << path << ": scene rejected\n";
        return false;
    }
    scene = std::move(*loaded.scene);
    return true;
}

int usageError(const std::string& command, const std::string& message) {
    std::cerr << "gridcull " << command << ": " << message << "\n"
              << "try 'gridcull " << command << " --help'\n";
    return kExitUsage;
}

void printUnusedNotes(const std::string& command, const KnobOptions& knobs,
                      const std::vector<std::string>& algorithms) {
    for (const std::string& note : knobs.unusedNotes(algorithms))
        std::cerr << "gridcull " << command << ": note: " << note << "\n";
}

int runCli(int argc, char** argv) {
    // The libraries report bad input as values; this catches what is left
    // (out of memory, say) so that the process still ends with a message.
    try {
        return dispatch(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "gridcull: " << e.what() << "\n";
    } catch (...) {
        std::cerr << "gridcull: unexpected error\n";
    }
    return kExitFailure;
}

}  // namespace gridcull
