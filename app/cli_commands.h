// The subcommands of app/cli.h, each a CLI11 subcommand with its own options
// (declared by its add function) and a run function called after parsing.
// Internal to the command line.
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli.h"
#include "app/cli_options.h"
#include "app/window.h"

namespace gridcull {

struct CullCommand {
    std::string scene, algo, out;
    long long frames = -1;
    KnobOptions knobs;
    const CLI::Option* out_option = nullptr;  // given: write to `out`
};
CLI::App* addCullCommand(CLI::App& app, CullCommand& c);
int runCull(const CullCommand& c);

struct BenchCommand {
    std::string scene, algo, csv, seek;
    std::string draw;      // --draw gl: draw each PVS and time it
    std::string baseline;  // --baseline NAME: the row ratios are taken against
    double query_cost_us = -1.0;  // --query-cost US: the query cost model's column
    long long frames = -1, runs = 5;
    bool no_quality = false;
    KnobOptions knobs;
    const CLI::Option* csv_option = nullptr;  // given: write `csv`
};
CLI::App* addBenchCommand(CLI::App& app, BenchCommand& c);
int runBench(const BenchCommand& c);
// bench --seek: the window's steps forward and back timed instead of culling
// (app/cli_bench_seek.cpp).
int runSeekBench(const BenchCommand& c, const Scene& scene, const std::vector<AlgoVariant>& algos);

struct TradeCommand {
    std::string scene, algo, out, draw;
    std::vector<double> targets;  // --target R[,S...]: a pick for each
    bool replot = false;          // --replot: from DIR/trade.csv, no sweep
    long long frames = -1, runs = 3;
    KnobOptions knobs;
};
CLI::App* addTradeCommand(CLI::App& app, TradeCommand& c);
int runTrade(const TradeCommand& c);

// `shot` and `view` share the window's options.
struct WindowCommand {
    std::string scene, algo = defaultAlgorithm(), out, view = "main";
    std::string compare;  // --compare B: a second culler beside the first
    std::string lesson;   // --lesson FILE
    std::string overlays;  // --overlays PRESET
    long long frame = 0, width = 1280, height = 720, exit_after = 0;
    long long step = 1;   // shot and record: the lesson step shown, from 1
    const CLI::Option* frame_option = nullptr;  // shot: --frame, required without --lesson
    bool play = false;
    double ui_scale = 1.0;
    KnobOptions knobs;
};
// The options shot, view and record share (SCENE, --algo, --compare,
// --lesson, sizes, knobs), and their checks: kExitOk when the window may open,
// `scene` loaded and `view` set. With a lesson SCENE may be left out: the
// first step's scene is then the one loaded.
void addWindowOptions(CLI::App& cmd, WindowCommand& c);
int prepareWindowCommand(const std::string& command, const WindowCommand& c, Scene& scene,
                         ViewOptions& view);
CLI::App* addShotCommand(CLI::App& app, WindowCommand& c);
int runShot(const WindowCommand& c);
CLI::App* addViewCommand(CLI::App& app, WindowCommand& c);
int runView(const WindowCommand& c);

struct RecordCommand {
    WindowCommand window;  // its frame is --from
    long long from = 0, to = -1;
    std::string out;
};
CLI::App* addRecordCommand(CLI::App& app, RecordCommand& c);
int runRecord(const RecordCommand& c);

struct KnobsCommand {
    bool markdown = false;
};
CLI::App* addKnobsCommand(CLI::App& app, KnobsCommand& c);
int runKnobs(const KnobsCommand& c);
// `counters` shares KnobsCommand's one flag, --markdown.
CLI::App* addCountersCommand(CLI::App& app, KnobsCommand& c);
int runCounters(const KnobsCommand& c);

// Prints each note of KnobOptions::unusedNotes as "gridcull CMD: note: ...".
void printUnusedNotes(const std::string& command, const KnobOptions& knobs,
                      const std::vector<std::string>& algorithms);

}  // namespace gridcull
