// `gridcull knobs [--markdown]`: every knob of every family, from the registry,
// with its range, default and what it trades; --markdown prints the table of
// docs/LIMITS.md. `gridcull counters [--markdown]`: every counter with its
// meaning, the table of docs/ARCHITECTURE.md. Tests keep both tables equal to
// this output.
#include <cstdio>

#include "app/cli.h"
#include "app/cli_commands.h"
#include "culling/api/counters.h"
#include "culling/registry/registry.h"
#include "ui/registry/family_views.h"

namespace gridcull {

namespace {

std::string rangeCell(const Knob& knob) {
    std::string range = knobRangeText(knob).substr(5);  // "1 to 1024"
    return (knob.kind == KnobKind::Integer ? "integer " : "") + range;
}

// The values trade sweeps, and the algorithms that read the knob when not all.
std::string sweepCell(const Knob& knob) {
    std::string cell;
    for (double v : knob.sweep) cell += (cell.empty() ? "" : ", ") + knobValueText(knob, v);
    if (cell.empty()) cell = "not swept";
    if (!knob.read_by.empty()) {
        std::string readers;
        for (const std::string& r : knob.read_by) readers += (readers.empty() ? "" : ", ") + r;
        cell += " (" + readers + " only)";
    }
    return cell;
}

}  // namespace

CLI::App* addKnobsCommand(CLI::App& app, KnobsCommand& c) {
    CLI::App* cmd = app.add_subcommand(
        "knobs",
        "Lists every knob of every algorithm family (the flags of cull, bench, shot and\n"
        "view, and bench's NAME:FLAG=VALUE entries) and the window's view flags, with\n"
        "their ranges, defaults and what they trade.");
    cmd->add_flag("--markdown", c.markdown, "print the table of docs/LIMITS.md");
    return cmd;
}

int runKnobs(const KnobsCommand& c) {
    if (c.markdown) {
        std::printf("| flag | family | values | default | what it trades | trade sweeps |\n");
        std::printf("| --- | --- | --- | --- | --- | --- |\n");
        for (const FamilyEntry& family : families())
            for (const Knob& knob : family.knobs)
                std::printf("| `--%s` | %s | %s | %s | %s | %s |\n", knob.flag.c_str(),
                            family.title.c_str(), rangeCell(knob).c_str(),
                            knobDefaultText(knob).c_str(), knob.help.c_str(),
                            sweepCell(knob).c_str());
        for (const FamilyViewEntry& view : familyViews()) {
            const FamilyEntry* family = findFamily(view.family);
            for (const Knob& flag : view.flags)
                std::printf("| `--%s` (shot, view) | %s | %s | %s | %s | not swept |\n",
                            flag.flag.c_str(),
                            family ? family->title.c_str() : view.family.c_str(),
                            rangeCell(flag).c_str(), knobDefaultText(flag).c_str(),
                            flag.help.c_str());
        }
        return kExitOk;
    }
    for (const FamilyEntry& family : families()) {
        if (family.knobs.empty()) continue;
        std::printf("%s:\n", family.title.c_str());
        for (const Knob& knob : family.knobs)
            std::printf("  --%-20s %s, default %s\n  %22s %s\n  %22s trade sweeps: %s\n",
                        knob.flag.c_str(), rangeCell(knob).c_str(), knobDefaultText(knob).c_str(),
                        "", knob.help.c_str(), "", sweepCell(knob).c_str());
    }
    std::printf("what the window shows (shot, view):\n");
    for (const Knob* flag : allViewFlags())
        std::printf("  --%-20s %s, default %s\n  %22s %s\n", flag->flag.c_str(),
                    rangeCell(*flag).c_str(), knobDefaultText(*flag).c_str(), "",
                    flag->help.c_str());
    return kExitOk;
}

CLI::App* addCountersCommand(CLI::App& app, KnobsCommand& c) {
    CLI::App* cmd = app.add_subcommand(
        "counters",
        "Lists every counter the algorithms report (the stats of cull's JSON lines,\n"
        "bench's counter columns, the window's statistics) with what it counts.");
    cmd->add_flag("--markdown", c.markdown, "print the table of docs/ARCHITECTURE.md");
    return cmd;
}

int runCounters(const KnobsCommand& c) {
    if (c.markdown) std::printf("| counter | what it counts |\n| --- | --- |\n");
    for (const CounterInfo& info : kCounters) {
        if (c.markdown)
            std::printf("| `%s` | %s |\n", info.name, info.meaning);
        else
            std::printf("  %-18s %s\n", info.name, info.meaning);
    }
    return kExitOk;
}

}  // namespace gridcull
