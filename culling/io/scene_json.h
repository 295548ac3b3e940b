// JSON reading for the scene loader: parsing with file positions, and typed field
// readers that report every problem as "FILE: json.path: must be ..., got ..."
// (scene-format.md, "Errors"). Internal to culling/scene_loader*.cpp: it exposes
// nlohmann::json, which nothing outside the loader should depend on.
// Nothing here throws: callers may still wrap calls in a catch-all for bad_alloc.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "culling/io/scene_loader.h"

namespace gridcull {

using Json = nlohmann::json;

// Collects messages for one file; each is prefixed by the file's display name.
class ErrorList {
public:
    explicit ErrorList(std::string file) : file_(std::move(file)) {}
    // "FILE: path: message"
    void add(const std::string& path, const std::string& message);
    // "FILE:LINE:COL: parse error: message"
    // A syntax error at line:column, inside the value at JSON `path` ("" at top level).
    void addAt(int line, int column, const std::string& path, const std::string& message);
    // "FILE: message", for problems that have no place in the file.
    void addGeneral(const std::string& message);
    bool empty() const { return count_ == 0; }
    size_t size() const { return count_; }
    const std::string& file() const { return file_; }
    // The messages, ending with a count of those not kept (see kMaxKept).
    std::vector<std::string> take();

    // A file with a million bad objects should not print a million lines: the
    // first kMaxKept messages are kept and the rest only counted.
    static constexpr size_t kMaxKept = 200;

private:
    void push(std::string message);
    std::string file_;
    std::vector<std::string> messages_;
    size_t count_ = 0;
};

// Nesting deeper than this is a parse error: no scene needs it, and it keeps
// every later recursive walk (dump, destruction) shallow.
constexpr int kMaxJsonDepth = 64;

// Parses `text` into `out`. Syntax errors, numbers that overflow a double
// (1e400) and nesting deeper than kMaxJsonDepth are reported with line and
// column (1-based, column in bytes) and make it return false: `out` must not be
// used. A key repeated in one object is reported by JSON path; `out` then keeps
// the last value and the function still returns true, so checking can go on.
bool parseJson(const std::string& text, ErrorList& errors, Json& out);

// Where a byte offset lies in `text`, 1-based.
void lineAndColumn(const std::string& text, size_t byte_offset, int& line, int& column);

std::string childPath(const std::string& path, const std::string& key);
std::string indexPath(const std::string& path, size_t index);
// A short rendering of a value for "got ...": JSON text, cut at 60 characters.
std::string describe(const Json& value);
// A double as short text: 2.5, 1e+07, 0.1.
std::string formatNumber(double value);

// Accepted range and wording of one numeric field. Every number must also be
// finite and at most kMaxMagnitude in size, which is checked first.
struct NumberRule {
    const char* expected = "a finite number";  // completes "must be ..."
    double min = -1e300;
    bool min_exclusive = false;
    double max = 1e300;
    bool max_exclusive = false;
};

// Every number read as a coordinate, size, speed or time must be at most this
// in magnitude (scene_loader.h explains the limit).
constexpr double kMaxMagnitude = kMaxSceneCoordinate;

// Typed access to one JSON object at `path`. Every reader reports its own
// problems and returns false when the value must not be used; a missing
// optional key leaves `out` unchanged and returns true.
class JsonObjectReader {
public:
    // Reports "must be an object" when `value` is not one; ok() is then false.
    JsonObjectReader(const Json& value, std::string path, ErrorList& errors);

    bool ok() const { return ok_; }
    const std::string& path() const { return path_; }
    std::string pathOf(const std::string& key) const { return childPath(path_, key); }
    bool has(const char* key) const;
    const Json* find(const char* key) const;

    // Reports every key not in `allowed`; `context` ends the message, e.g.
    // "for shape 'box'". Returns false when there was one.
    bool checkKeys(std::initializer_list<const char*> allowed, const std::string& context = "");
    // Reports a missing key. Returns false when it is missing.
    bool require(const char* key, const std::string& expected);

    bool number(const char* key, bool required, const NumberRule& rule, double& out);
    bool integer(const char* key, bool required, int64_t min, int64_t max,
                 const std::string& expected, int64_t& out);
    bool unsignedInteger(const char* key, bool required, uint64_t& out);
    bool string(const char* key, bool required, std::string& out);
    // `count` numbers (2 or 3), each finite and within kMaxMagnitude; the unused
    // components of `out` are set to 0.
    bool vector(const char* key, bool required, int count, glm::dvec3& out);
    // A [min, max] pair with min <= max, both satisfying `rule`.
    bool range(const char* key, bool required, const NumberRule& rule, double& lo, double& hi);
    // Two or three integers, each in [min, max].
    bool integers(const char* key, bool required, int count, int64_t min, int64_t max,
                  const std::string& expected, int64_t* out);

private:
    const Json* value_;
    std::string path_;
    ErrorList& errors_;
    bool ok_;
};

// Checks one JSON value as `count` numbers (a vector), reporting at `path`.
bool readVectorValue(const Json& value, const std::string& path, int count, ErrorList& errors,
                     glm::dvec3& out);

// Checks one JSON value as a number under `rule`, reporting at `path`.
bool readNumberValue(const Json& value, const std::string& path, const NumberRule& rule,
                     ErrorList& errors, double& out);

}  // namespace gridcull
