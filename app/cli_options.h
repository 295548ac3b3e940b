// How the command line gets the registry's knobs and the families' view flags:
// each is a CLI11 option of the commands that take it, grouped by family in
// --help, with its range and default from its Knob; after parsing, each value
// given is checked by parseKnobValue (culling/api/knobs.h), so the command line,
// bench's NAME:FLAG=VALUE entries and the window check values the same way.
// Also the help's layout and the text every culling command's help ends with.
#pragma once
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "culling/api/knobs.h"

namespace gridcull {

class KnobOptions {
public:
    // Adds every knob of the registry to `command`; with `view_flags`, also every
    // family's view flags.
    void addTo(CLI::App& command, bool view_flags);
    // After parsing: the values given, checked. False with `error` naming the
    // flag and what was expected.
    bool read(KnobValues& knobs, KnobValues& view_flags, std::string& error) const;
    // Notes (one line each) for knobs and view flags given that none of
    // `algorithms` reads: they belong to another family.
    std::vector<std::string> unusedNotes(const std::vector<std::string>& algorithms) const;

private:
    struct Bound {
        const Knob* knob = nullptr;
        bool view_flag = false;
        std::string text;
        CLI::Option* option = nullptr;
    };
    std::deque<Bound> bound_;  // CLI11 keeps pointers to `text`: a deque never moves them
};

// The help layout of every command: "usage:", options in a column with their
// description wrapped to 80 characters.
std::shared_ptr<CLI::Formatter> helpFormatter();

// The algorithms (name, dimensions, one line each) and the scene limits
// (docs/LIMITS.md), built from the registry and the constants that enforce the
// limits, so help cannot drift from them. Every culling command's help ends with it.
std::string cullingHelpFooter(const std::vector<std::string>& algorithms);

// CLI11's message, and a hint when an unknown option is the tail of a knob's
// flag (--rays: "did you mean --oracle-rays?").
std::string parseErrorMessage(const CLI::ParseError& error);

}  // namespace gridcull
