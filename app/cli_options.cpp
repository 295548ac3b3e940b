#include "app/cli_options.h"

#include <cctype>
#include <cstdio>
#include <sstream>

#include "app/app_cullers.h"
#include "culling/registry/registry.h"
#include "culling/scene/scene_limits.h"
#include "grid/regular_grid.h"
#include "ui/registry/family_views.h"

namespace gridcull {

namespace {

constexpr size_t kHelpWidth = 80;
constexpr size_t kNameColumn = 24;

// Words of `text` wrapped to lines of at most `width - indent` characters, every
// line after the first indented by `indent` spaces.
std::string wrap(const std::string& text, size_t indent, size_t width) {
    std::istringstream words(text);
    std::string word, out, line;
    while (words >> word) {
        if (!line.empty() && indent + line.size() + 1 + word.size() > width) {
            out += line + "\n" + std::string(indent, ' ');
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    return out + line;
}

class HelpFormatter final : public CLI::Formatter {
public:
    HelpFormatter() { label("Usage", "usage"); }
    // CLI11 puts two blank lines between option groups; one reads better.
    std::string make_help(const CLI::App* app, std::string name,
                          CLI::AppFormatMode mode) const override {
        std::string text = CLI::Formatter::make_help(app, std::move(name), mode);
        for (size_t at = text.find("\n\n\n"); at != std::string::npos; at = text.find("\n\n\n", at))
            text.erase(at, 1);
        return text;
    }
    std::string make_option(const CLI::Option* opt, bool is_positional) const override {
        std::string name = "  " + make_option_name(opt, is_positional) + make_option_opts(opt);
        const std::string desc = make_option_desc(opt);
        if (name.size() + 1 > kNameColumn)
            name += "\n" + std::string(kNameColumn, ' ');
        else
            name.resize(kNameColumn, ' ');
        return name + wrap(desc, kNameColumn, kHelpWidth) + "\n";
    }
};

std::string knobDescription(const Knob& knob) {
    return knob.help + " (" + (knob.kind == KnobKind::Integer ? "an integer " : "") +
           knobRangeText(knob) + "; default " + knobDefaultText(knob) + ")";
}

const FamilyEntry* ownerOf(const Knob& knob, bool view_flag) {
    if (!view_flag) return familyOfKnob(knob.flag);
    const FamilyViewEntry* view = familyViewOfFlag(knob.flag);
    return view ? findFamily(view->family) : nullptr;
}

}  // namespace

void KnobOptions::addTo(CLI::App& command, bool view_flags) {
    const auto add = [&](const Knob* knob, bool view_flag) {
        const FamilyEntry* family = ownerOf(*knob, view_flag);
        Bound& b = bound_.emplace_back();
        b.knob = knob;
        b.view_flag = view_flag;
        b.option = command.add_option("--" + knob->flag, b.text, knobDescription(*knob));
        b.option->type_name(knob->kind == KnobKind::Integer ? "N" : "X");
        b.option->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // the last one wins
        const std::string title = family ? family->title : "other";
        b.option->group(view_flag ? title + ", what the window shows" : title + " knobs");
    };
    for (const Knob* knob : allKnobs()) add(knob, false);
    if (view_flags)
        for (const Knob* flag : allViewFlags()) add(flag, true);
}

bool KnobOptions::read(KnobValues& knobs, KnobValues& view_flags, std::string& error) const {
    for (const Bound& b : bound_) {
        if (b.option->count() == 0) continue;
        double value = 0.0;
        if (!parseKnobValue(*b.knob, b.text, value, error)) return false;
        (b.view_flag ? view_flags : knobs).set(b.knob->flag, value);
    }
    return true;
}

std::vector<std::string> KnobOptions::unusedNotes(
    const std::vector<std::string>& algorithms) const {
    std::vector<std::string> notes;
    for (const Bound& b : bound_) {
        if (b.option->count() == 0) continue;
        const FamilyEntry* owner = ownerOf(*b.knob, b.view_flag);
        if (!owner || owner->reference) continue;  // the reference runs with every algorithm
        bool used = false;
        for (const std::string& algo : algorithms) {
            const FamilyEntry* family = familyOfAlgorithm(algo);
            used = used || family == owner;
        }
        if (!used)
            notes.push_back("--" + b.knob->flag + " belongs to " + owner->title +
                            "; none of the algorithms run here reads it");
    }
    return notes;
}

std::shared_ptr<CLI::Formatter> helpFormatter() {
    return std::make_shared<HelpFormatter>();
}

std::string cullingHelpFooter(const std::vector<std::string>& algorithms) {
    std::string text = "algorithms (--algo), and the scenes they run on:\n";
    for (const std::string& name : algorithms) {
        // A -gl variant runs where its registry algorithm runs.
        const std::string base = registryAlgorithmOf(name);
        const AlgorithmEntry* entry = nullptr;
        if (!familyOfAlgorithm(base, &entry)) continue;
        const char* dims = entry->dimensions == kRuns2d   ? "2D"
                           : entry->dimensions == kRuns3d ? "3D"
                                                          : "2D, 3D";
        const std::string summary =
            base == name ? entry->summary : base + " drawn with OpenGL, a read-back per pixel query";
        char line[256];
        std::snprintf(line, sizeof line, "  %-20s %-7s ", name.c_str(), dims);
        text += line + wrap(summary, 31, kHelpWidth) + "\n";
    }
    char limits[1024];
    std::snprintf(
        limits, sizeof limits,
        "\nscene limits (docs/LIMITS.md); a file beyond them is rejected, exit status 3:\n"
        "  every number          finite and at most %.0f in magnitude (coordinates,\n"
        "                        sizes, speeds, times)\n"
        "  grid.resolution       at most %lld voxels in all (2D: 8192 x 8192; 3D: 406^3)\n"
        "  camera.fov_deg        3D: in (0, 180); 2D: in (0, 360]\n"
        "  camera.near, far      0 < near < far; aspect > 0\n"
        "  objects               at most %lld, listed and generated together\n"
        "  time.frames           1 to %lld; time.dt > 0\n"
        "\nexit status: 0 done, 2 bad command line, 3 scene rejected, 1 anything else.\n",
        kMaxSceneCoordinate, (long long)kMaxGridVoxels, (long long)kMaxSceneObjects,
        (long long)kMaxSceneFrames);
    return text + limits;
}

std::string parseErrorMessage(const CLI::ParseError& error) {
    std::string message = error.what();
    // An unknown --X that ends a knob's or view flag's name: that flag was renamed
    // to say whose it is.
    const std::string marker = "--";
    for (size_t at = message.find(marker); at != std::string::npos;
         at = message.find(marker, at + 2)) {
        size_t end = at + 2;
        while (end < message.size() &&
               (std::isalnum((unsigned char)message[end]) || message[end] == '-'))
            ++end;
        const std::string given = message.substr(at + 2, end - at - 2);
        if (given.empty() || findKnob(given) || findViewFlag(given)) continue;
        std::vector<const Knob*> flags = allKnobs();
        for (const Knob* f : allViewFlags()) flags.push_back(f);
        for (const Knob* f : flags) {
            const std::string& name = f->flag;
            if (name.size() > given.size() &&
                name.compare(name.size() - given.size(), given.size(), given) == 0 &&
                name[name.size() - given.size() - 1] == '-')
                message += "; did you mean --" + name + "?";
        }
    }
    return message;
}

}  // namespace gridcull
