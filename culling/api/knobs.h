// Knobs: the options of an algorithm family (and of the oracle), each one thing a
// user can turn to trade speed for accuracy. A family keeps its options in a
// struct of its own and describes each member once, in a KnobTable: the flag,
// the range, the help, and the member it sets (its default is the struct's).
// That one description drives the command line's flags and their help, the
// checking of values (the window's too), bench's NAME:FLAG=VALUE entries and
// the knob table of docs/LIMITS.md.
//
// Values travel between those places as KnobValues: the values set so far, by
// flag; a family reads its struct out of them with its table. Flags start with
// their family's prefix (the oracle's "oracle-"), so that two families' knobs
// never share a name.
#pragma once
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace gridcull {

enum class KnobKind : uint8_t { Integer, Real };

struct Knob {
    std::string flag;  // without the dashes, e.g. "oracle-res"
    KnobKind kind = KnobKind::Real;
    double min = 0.0, max = 0.0;  // the accepted values, inclusive
    // The value when none is set. It lies in [min, max], unless `automatic` is
    // set: then it is a marker (outside the range) for a value derived at run time.
    double default_value = 0.0;
    std::string automatic;          // one word for that marker, e.g. "scene"
    std::string automatic_meaning;  // what it stands for, e.g. "the scene's grid.resolution"
    std::string help;               // what it does, and what turning it up or down costs
    // The values `gridcull trade` tries, one knob at a time from the defaults
    // (docs/LIMITS.md lists them): the knob's useful range, in [min, max];
    // empty: never swept.
    std::vector<double> sweep;
    // The algorithms of its family that read it; empty: every one of them.
    std::vector<std::string> read_by;
};

// Whether algorithm `name` (of the knob's family) reads `knob`.
inline bool knobReadBy(const Knob& knob, const std::string& name) {
    if (knob.read_by.empty()) return true;
    for (const std::string& reader : knob.read_by)
        if (reader == name) return true;
    return false;
}

// Reads `text` as a value of `knob`: an integer (Integer) or a finite number
// (Real) within [min, max], nothing else. False with `error` saying what was
// expected, e.g. "option --oracle-res: expected an integer from 16 to 8192, got '0'".
bool parseKnobValue(const Knob& knob, const std::string& text, double& value, std::string& error);
// "from 1 to 1024", "from 0.001 to 86400".
std::string knobRangeText(const Knob& knob);
// The value as a user writes it: "32", "0.5"; the `automatic` word for the marker.
std::string knobValueText(const Knob& knob, double value);
// The default for help: "32", or the automatic marker's meaning.
std::string knobDefaultText(const Knob& knob);

class KnobValues {
public:
    // Sets a knob's value; callers check it with parseKnobValue first.
    void set(const std::string& flag, double value) { values_[flag] = value; }
    void unset(const std::string& flag) { values_.erase(flag); }
    bool has(const std::string& flag) const { return values_.count(flag) != 0; }
    // The value set, or the knob's default.
    double get(const Knob& knob) const {
        const auto found = values_.find(knob.flag);
        return found == values_.end() ? knob.default_value : found->second;
    }
    const std::map<std::string, double>& set_values() const { return values_; }

private:
    std::map<std::string, double> values_;
};

// The knobs of one options struct. Build it with knob() and derivedKnob():
//   const KnobTable<OracleOptions> table{
//       knob("oracle-res", &OracleOptions::resolution, 16, 8192, "..."), ...};
template <class Options>
class KnobTable {
public:
    // A knob and how to read and set the member it stands for.
    struct Entry {
        Knob knob;
        std::function<double(const Options&)> get;
        std::function<void(Options&, double)> set;
    };

    KnobTable(std::initializer_list<Entry> entries) : entries_(entries) {
        const Options defaults{};
        for (Entry& e : entries_) {
            e.knob.default_value = e.get(defaults);
            knobs_.push_back(e.knob);
        }
    }

    const std::vector<Knob>& knobs() const { return knobs_; }

    // Options{} with every value of `values` that names one of these knobs.
    Options read(const KnobValues& values) const {
        Options options{};
        for (const Entry& e : entries_) {
            if (!values.has(e.knob.flag)) continue;
            e.set(options, values.get(e.knob));
        }
        return options;
    }

private:
    std::vector<Entry> entries_;
    std::vector<Knob> knobs_;
};

// One knob of an options struct; its default is the struct's member default.
template <class Options, class T>
typename KnobTable<Options>::Entry knob(const char* flag, T Options::*member, double min,
                                        double max, const char* help) {
    static_assert(std::is_same_v<T, int> || std::is_same_v<T, double>, "int or double knobs");
    Knob k;
    k.flag = flag;
    k.kind = std::is_same_v<T, int> ? KnobKind::Integer : KnobKind::Real;
    k.min = min;
    k.max = max;
    k.help = help;
    return {k, [member](const Options& o) { return double(o.*member); },
            [member](Options& o, double v) {
                o.*member = std::is_same_v<T, int> ? T(std::llround(v)) : T(v);
            }};
}

// A knob whose unset value (the member's default, outside [min, max]) stands
// for one derived at run time: `automatic` is its one-word name, `meaning` says
// what it follows.
template <class Options, class T>
typename KnobTable<Options>::Entry derivedKnob(const char* flag, T Options::*member, double min,
                                               double max, const char* automatic,
                                               const char* meaning, const char* help) {
    typename KnobTable<Options>::Entry e = knob(flag, member, min, max, help);
    e.knob.automatic = automatic;
    e.knob.automatic_meaning = meaning;
    return e;
}

// A knob entry with the values trade sweeps it over (Knob::sweep).
template <class Entry>
Entry swept(Entry entry, std::initializer_list<double> values) {
    entry.knob.sweep = values;
    return entry;
}

// A knob entry that only the algorithms `names` of its family read (Knob::read_by).
template <class Entry>
Entry readBy(Entry entry, std::initializer_list<const char*> names) {
    for (const char* name : names) entry.knob.read_by.push_back(name);
    return entry;
}

}  // namespace gridcull
