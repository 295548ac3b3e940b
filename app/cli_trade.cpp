// `gridcull trade SCENE --algo A[,B...] [--target R] [--out DIR]`: the speed /
// accuracy trade of each algorithm named, measured over its family's knobs
// (app/trade_sweep.h), written as a CSV and PNG plots with the Pareto fronts
// marked (app/trade_report.h, ui/trade_plot.h); with --target, the cheapest
// setting whose PVS/exact is at most R with no false cull (ui/trade_front.h).
// Ctrl-C stops the sweep after the current frame: the settings measured so far
// are written, whole, and the command exits 130.
#include <signal.h>
#include <sys/stat.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <iostream>

#include "app/app_cullers.h"
#include "app/cli.h"
#include "app/cli_commands.h"
#include "app/output_file.h"
#include "app/progress_bar.h"
#include "app/pvs_draw_timer.h"
#include "app/trade_plot_png.h"
#include "app/trade_report.h"
#include "app/trade_sweep.h"
#include "culling/registry/registry.h"

namespace gridcull {

namespace {

constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as a shell reports it
constexpr int kPlotWidth = 960, kPlotHeight = 600;

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void onInterrupt(int) { g_interrupted.store(true); }

bool makeDirectory(const std::string& dir, std::string& error) {
    if (::mkdir(dir.c_str(), 0777) == 0 || errno == EEXIST) {
        struct stat st;
        if (::stat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return true;
        error = "'" + dir + "' exists and is not a folder";
        return false;
    }
    error = "cannot make the folder '" + dir + "': " + std::strerror(errno);
    return false;
}

bool writeText(const std::string& path, const std::string& text, std::string& error) {
    OutputFile file;
    if (!file.open(path, error)) return false;
    if (std::fwrite(text.data(), 1, text.size(), file.stream()) != text.size()) {
        error = "writing '" + path + "' failed";
        return false;
    }
    return file.commit(error);
}

std::string describePick(const TradePoint& p) {
    char buf[256];
    if (p.frame_ms > 0.0)
        std::snprintf(buf, sizeof buf, "frame %.4g ms (cull %.4g + draw %.4g)", p.frame_ms,
                      p.cull_ms, p.draw_ms);
    else
        std::snprintf(buf, sizeof buf, "cull %.4g ms", p.cull_ms);
    char rest[128];
    std::snprintf(rest, sizeof rest, ", PVS/exact %.3f, %.1f MiB", p.pvs_ratio,
                  p.memory_bytes / (1 << 20));
    return p.setting + ": " + buf + rest;
}

// The picks for --target: over all the algorithms, then per algorithm.
void printPicks(const std::vector<TradePoint>& points, const std::vector<std::string>& algorithms,
                double target) {
    const int best = cheapestWithin(points, target);
    std::printf("target PVS/exact <= %g with no false cull:\n", target);
    if (best < 0)
        std::printf("  no setting measured is accurate enough\n");
    else
        std::printf("  cheapest of all: %s\n", describePick(points[size_t(best)]).c_str());
    if (algorithms.size() < 2) return;
    for (const std::string& a : algorithms) {
        const std::vector<size_t> own = pointsOf(points, a);
        std::vector<TradePoint> subset;
        for (size_t i : own) subset.push_back(points[i]);
        const int pick = cheapestWithin(subset, target);
        if (pick < 0)
            std::printf("  %s: none accurate enough\n", a.c_str());
        else
            std::printf("  %s: %s\n", a.c_str(), describePick(subset[size_t(pick)]).c_str());
    }
}

bool writePlots(const std::string& dir, const std::string& scene_name,
                const std::vector<TradePoint>& points, const std::vector<std::string>& algorithms,
                double target, std::string& error) {
    TradePlotPng png;
    if (!png.init(kPlotWidth, kPlotHeight, error)) return false;
    TradePlotInput input;
    input.points = &points;
    input.target = target;
    input.title = scene_name + ": " + std::to_string(points.size()) + " settings";
    input.series_order = algorithms;  // each algorithm's own plot keeps its colour
    if (target > 0) input.chosen = cheapestWithin(points, target);
    if (!png.write(input, dir + "/trade.png", error)) return false;
    if (algorithms.size() < 2) return true;
    for (const std::string& a : algorithms) {
        std::vector<TradePoint> subset;
        for (size_t i : pointsOf(points, a)) subset.push_back(points[i]);
        if (subset.empty()) continue;
        TradePlotInput own = input;
        own.points = &subset;
        own.title = scene_name + ": " + a + ", " + std::to_string(subset.size()) + " settings";
        own.chosen = target > 0 ? cheapestWithin(subset, target) : -1;
        if (!png.write(own, dir + "/" + a + ".png", error)) return false;
    }
    return true;
}

}  // namespace

CLI::App* addTradeCommand(CLI::App& app, TradeCommand& c) {
    CLI::App* cmd = app.add_subcommand(
        "trade",
        "Measures each algorithm's speed / accuracy trade on SCENE: its defaults, then\n"
        "each knob of its family (`gridcull knobs`) over the values docs/LIMITS.md lists,\n"
        "one knob at a time, every setting timed on the same frames R runs, judged by\n"
        "the exact oracle. Writes DIR/trade.csv (one row per setting: median and 95th\n"
        "percentile cull, draw and frame ms, memory, PVS/exact, false culls, Pareto\n"
        "front) and DIR/trade.png (and one PNG per algorithm): PVS/exact against cost,\n"
        "the fronts joined. With --target R, names the cheapest setting whose\n"
        "PVS/exact is at most R with no false cull. Ctrl-C writes what was measured.");
    cmd->add_option("SCENE", c.scene, "the scene file")->required()->type_name("");
    cmd->add_option("--algo", c.algo, "algorithms, comma-separated (listed below)")
        ->required()
        ->type_name("A[,B...]");
    cmd->add_option("--target", c.targets,
                    "the PVS/exact to reach, 1 to 1e6: pick the cheapest setting within it\n"
                    "(several, comma-separated: a pick for each)")
        ->delimiter(',')
        ->check(CLI::Range(1.0, 1e6).description(""))
        ->type_name("R[,S...]");
    cmd->add_option("--out", c.out, "the folder to write (default: trade-SCENENAME)")
        ->type_name("DIR");
    cmd->add_option("--frames", c.frames,
                    "frames to run, 1 to 1000000 (default: the scene's time.frames)")
        ->check(CLI::Range(1LL, 1000000LL).description(""))
        ->type_name("N");
    cmd->add_option("--runs", c.runs, "repetitions of each setting, 1 to 1000 (default 3)")
        ->check(CLI::Range(1LL, 1000LL).description(""))
        ->type_name("N");
    cmd->add_option("--draw", c.draw,
                    "gl: also draw each PVS (as bench --draw gl) and trade frame time")
        ->check(CLI::IsMember({"gl"}))
        ->type_name("gl");
    cmd->add_flag("--replot", c.replot,
                  "measure nothing: read DIR/trade.csv as written before, print its table\n"
                  "and the --target picks, and draw the plots again");
    c.knobs.addTo(*cmd, false);
    cmd->footer(cullingHelpFooter(appAlgorithmNames()));
    return cmd;
}

namespace {

// trade --replot: the table, picks and plots of a CSV written before.
int replot(const TradeCommand& c, const std::string& dir, const std::string& scene_name) {
    const std::string path = dir + "/trade.csv";
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::cerr << "gridcull trade: --replot: cannot read '" << path << "'\n";
        return kExitFailure;
    }
    std::stringstream text;
    text << in.rdbuf();
    std::vector<TradeSetting> settings;
    std::vector<TradePoint> points;
    std::string error;
    if (!parseTradeCsv(text.str(), settings, points, error)) {
        std::cerr << "gridcull trade: " << path << ": " << error << "\n";
        return kExitFailure;
    }
    std::vector<std::string> algorithms;
    for (const TradePoint& p : points)
        if (std::find(algorithms.begin(), algorithms.end(), p.algorithm) == algorithms.end())
            algorithms.push_back(p.algorithm);
    std::fputs(formatTradeTable(points).c_str(), stdout);
    for (double target : c.targets) printPicks(points, algorithms, target);
    if (points.empty()) return kExitOk;
    if (!writePlots(dir, scene_name, points, algorithms,
                    c.targets.empty() ? 0.0 : c.targets.front(), error)) {
        std::cerr << "gridcull trade: no plots: " << error << "\n";
        return kExitFailure;
    }
    std::printf("wrote %s/trade.png%s\n", dir.c_str(),
                algorithms.size() > 1 ? " and one PNG per algorithm" : "");
    return kExitOk;
}

}  // namespace

int runTrade(const TradeCommand& c) {
    std::string error;
    KnobValues base, view_flags;
    if (!c.knobs.read(base, view_flags, error)) return usageError("trade", error);
    std::vector<std::string> algorithms;
    if (!splitAlgorithms(c.algo, algorithms, error, appAlgorithmNames()))
        return usageError("trade", error + " (trade sweeps each algorithm's knobs itself)");
    Scene scene;
    if (!loadSceneOrReport(c.scene, scene)) return kExitSceneRejected;
    for (const std::string& a : algorithms)
        if (!algorithmFits(registryAlgorithmOf(a), scene, error))
            return usageError("trade", c.scene + ": " + error);
    printUnusedNotes("trade", c.knobs, algorithms);
    const std::string dir = c.out.empty() ? "trade-" + scene.name : c.out;
    if (c.replot) return replot(c, dir, scene.name);
    if (!makeDirectory(dir, error)) {
        std::cerr << "gridcull trade: " << error << "\n";
        return kExitFailure;
    }

    const int frames = int(c.frames < 0 ? scene.frames : c.frames), runs = int(c.runs);
    const std::vector<TradeSetting> settings = tradeSettings(algorithms, base);
    TradeSweep sweep(scene, frames, runs, &g_interrupted);
    PvsDrawTimer draw_timer;
    if (!c.draw.empty()) {
        if (!draw_timer.init(scene, referenceResolution(base), error)) {
            std::cerr << "gridcull trade: --draw gl: " << error << "\n";
            return kExitFailure;
        }
        sweep.setDraw([&](const Camera& camera, double t, const std::vector<int>& pvs) {
            return draw_timer.draw(scene, camera, t, pvs);
        });
    }
    ProgressBar progress(sweep.steps(settings.size()));
    sweep.setStep([&] { progress.step(); });
    std::printf("scene: %s (%dD, %zu objects), frames 0..%d, %d runs, %zu settings of %s%s\n",
                scene.name.c_str(), scene.dimensions, scene.objects.size(), frames - 1, runs,
                settings.size(), c.algo.c_str(), c.draw.empty() ? "" : ", drawn");
    std::fflush(stdout);

    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    struct sigaction previous {};
    sigaction(SIGINT, &action, &previous);
    std::vector<TradePoint> points;
    std::vector<TradeSetting> measured;
    bool interrupted = !sweep.prepare(base, error);
    if (interrupted && !g_interrupted.load()) {
        sigaction(SIGINT, &previous, nullptr);
        std::cerr << "gridcull trade: " << error << "\n";
        return kExitFailure;
    }
    for (size_t i = 0; i < settings.size() && !interrupted; ++i) {
        TradePoint point;
        switch (sweep.measure(settings[i], point, error)) {
            case TradeSweep::Outcome::Measured:
                points.push_back(point);
                measured.push_back(settings[i]);
                break;
            case TradeSweep::Outcome::Stopped:
                interrupted = true;
                break;
            case TradeSweep::Outcome::Failed:
                sigaction(SIGINT, &previous, nullptr);
                std::cerr << "gridcull trade: " << settings[i].label << ": " << error << "\n";
                return kExitFailure;
        }
    }
    sigaction(SIGINT, &previous, nullptr);
    if (interrupted) std::fputs("\n", stderr);  // past the progress bar

    std::fputs(formatTradeTable(points).c_str(), stdout);
    if (!points.empty())
        for (double target : c.targets) printPicks(points, algorithms, target);
    if (!writeText(dir + "/trade.csv", formatTradeCsv(measured, points), error)) {
        std::cerr << "gridcull trade: " << error << "\n";
        return kExitFailure;
    }
    std::printf("wrote %s/trade.csv (%zu of %zu settings)\n", dir.c_str(), points.size(),
                settings.size());
    // The CSV is written whatever happens to the plots, which need a display.
    bool plotted = true;
    if (!points.empty()) {
        // The plots mark the first target's pick.
        plotted = writePlots(dir, scene.name, points, algorithms,
                             c.targets.empty() ? 0.0 : c.targets.front(), error);
        if (plotted)
            std::printf("wrote %s/trade.png%s\n", dir.c_str(),
                        algorithms.size() > 1 ? " and one PNG per algorithm" : "");
        else
            std::cerr << "gridcull trade: no plots: " << error << "\n";
    }
    if (interrupted) {
        std::fprintf(stderr,
                     "gridcull trade: interrupted: %zu of %zu settings measured; the CSV holds "
                     "those, whole\n",
                     points.size(), settings.size());
        return kExitInterrupted;
    }
    return plotted ? kExitOk : kExitFailure;
}

}  // namespace gridcull
