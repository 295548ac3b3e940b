#include "culling/io/scene_json.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>

namespace gridcull {

void ErrorList::push(std::string message) {
    ++count_;
    if (messages_.size() < kMaxKept) messages_.push_back(std::move(message));
}

std::vector<std::string> ErrorList::take() {
    std::vector<std::string> out = std::move(messages_);
    if (count_ > out.size())
        out.push_back(file_ + ": " + std::to_string(count_ - out.size()) +
                      " more problems not shown");
    messages_.clear();
    count_ = 0;
    return out;
}

void ErrorList::add(const std::string& path, const std::string& message) {
    push(file_ + ": " + (path.empty() ? std::string("(top level)") : path) + ": " + message);
}

void ErrorList::addAt(int line, int column, const std::string& path, const std::string& message) {
    push(file_ + ":" + std::to_string(line) + ":" + std::to_string(column) + ": parse error" +
         (path.empty() ? std::string() : " in " + path) + ": " + message);
}

void ErrorList::addGeneral(const std::string& message) {
    push(file_ + ": " + message);
}

void lineAndColumn(const std::string& text, size_t byte_offset, int& line, int& column) {
    line = 1;
    size_t line_start = 0;
    const size_t end = std::min(byte_offset, text.size());
    for (size_t i = 0; i < end; ++i) {
        if (text[i] == '\n') {
            ++line;
            line_start = i + 1;
        }
    }
    column = int(end - line_start) + 1;
}

std::string childPath(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
}

std::string indexPath(const std::string& path, size_t index) {
    return path + "[" + std::to_string(index) + "]";
}

std::string formatNumber(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.10g", value);
    return buffer;
}

std::string describe(const Json& value) {
    std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
    constexpr size_t kMaxShown = 60;
    if (text.size() > kMaxShown) text = text.substr(0, kMaxShown) + "...";
    return text;
}

namespace {

// Builds the DOM through nlohmann's own SAX DOM builder, and on the way keeps
// the JSON path of the current value so that duplicate keys (which nlohmann
// silently collapses to the last one) can be reported, limits nesting depth, and
// captures the byte position of the first syntax error instead of throwing.
class TrackingSax {
public:
    using Dom = nlohmann::detail::json_sax_dom_parser<Json>;

    TrackingSax(Json& out, ErrorList& errors) : dom_(out, false), errors_(errors) {}

    bool null() { return value() && dom_.null(); }
    bool boolean(bool v) { return value() && dom_.boolean(v); }
    bool number_integer(Json::number_integer_t v) { return value() && dom_.number_integer(v); }
    bool number_unsigned(Json::number_unsigned_t v) { return value() && dom_.number_unsigned(v); }
    bool number_float(Json::number_float_t v, const Json::string_t& s) {
        return value() && dom_.number_float(v, s);
    }
    bool string(Json::string_t& v) { return value() && dom_.string(v); }
    bool binary(Json::binary_t& v) { return value() && dom_.binary(v); }
    bool start_object(std::size_t n) { return open(false) && dom_.start_object(n); }
    bool end_object() {
        frames_.pop_back();
        return dom_.end_object();
    }
    bool start_array(std::size_t n) { return open(true) && dom_.start_array(n); }
    bool end_array() {
        frames_.pop_back();
        return dom_.end_array();
    }
    bool key(Json::string_t& k) {
        Frame& frame = frames_.back();
        frame.key = k;
        if (!frame.keys.insert(k).second)
            errors_.add(currentPath(), "key appears twice in the same object");
        return dom_.key(k);
    }
    template <class Exception>
    bool parse_error(std::size_t position, const std::string& token, const Exception& ex) {
        failed_ = true;
        error_position_ = position;
        error_message_ = ex.what();
        error_token_ = token;
        error_id_ = ex.id;
        error_path_ = valuePath();
        return false;
    }

    bool failed() const { return failed_; }
    size_t errorPosition() const { return error_position_; }
    const std::string& errorMessage() const { return error_message_; }
    const std::string& errorToken() const { return error_token_; }
    int errorId() const { return error_id_; }
    // The JSON path of the value being read when the syntax error struck.
    const std::string& errorPath() const { return error_path_; }
    bool tooDeep() const { return too_deep_; }

private:
    struct Frame {
        bool is_array = false;
        size_t next_index = 0;
        std::string key;
        std::set<std::string> keys;
    };

    // Called at the start of every value: advances the enclosing array's index.
    bool value() {
        if (!frames_.empty() && frames_.back().is_array) ++frames_.back().next_index;
        return true;
    }
    bool open(bool is_array) {
        value();
        if (int(frames_.size()) >= kMaxJsonDepth) {
            too_deep_ = true;
            return false;
        }
        frames_.push_back(Frame{is_array, 0, {}, {}});
        return true;
    }
    std::string currentPath() const {
        std::string path;
        for (const Frame& frame : frames_) {
            if (frame.is_array) {
                path = indexPath(path, frame.next_index - 1);
            } else {
                path = childPath(path, frame.key);
            }
        }
        return path;
    }

    // Like currentPath, but inside an array names the element not yet started:
    // a syntax error strikes before value() has counted it.
    std::string valuePath() const {
        std::string path;
        for (size_t i = 0; i < frames_.size(); ++i) {
            const Frame& frame = frames_[i];
            if (frame.is_array) {
                const bool innermost = i + 1 == frames_.size();
                path = indexPath(path, innermost ? frame.next_index : frame.next_index - 1);
            } else if (!frame.key.empty() || i + 1 < frames_.size()) {
                path = childPath(path, frame.key);
            }
        }
        return path;
    }

    Dom dom_;
    ErrorList& errors_;
    std::vector<Frame> frames_;
    bool failed_ = false;
    bool too_deep_ = false;
    size_t error_position_ = 0;
    std::string error_message_;
    std::string error_token_;
    int error_id_ = 0;
    std::string error_path_;
};

// nlohmann's message starts "[json.exception.parse_error.101] parse error at
// line 3, column 5: " and we print our own position: keep only the reason.
std::string reasonOf(const std::string& what) {
    const size_t bracket = what.find("] ");
    std::string reason = bracket == std::string::npos ? what : what.substr(bracket + 2);
    const std::string prefix = "parse error";
    if (reason.compare(0, prefix.size(), prefix) == 0) {
        const size_t colon = reason.find(": ");
        if (colon != std::string::npos) reason = reason.substr(colon + 2);
    }
    return reason;
}

// The first byte of the JSON token whose last byte is at `last`: a string is
// scanned back to its opening quote, a number or literal over its characters.
size_t tokenStart(const std::string& text, size_t last) {
    if (last >= text.size()) return last;
    auto is_word = [](char ch) {
        return std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '+' || ch == '-';
    };
    size_t i = last;
    if (text[i] == '"') {
        while (i > 0) {
            --i;
            if (text[i] == '"' && (i == 0 || text[i - 1] != '\\')) return i;
        }
        return last;
    }
    if (!is_word(text[i])) return last;
    while (i > 0 && is_word(text[i - 1])) --i;
    return i;
}

}  // namespace

bool parseJson(const std::string& text, ErrorList& errors, Json& out) {
    TrackingSax sax(out, errors);
    const bool parsed = Json::sax_parse(text, &sax, Json::input_format_t::json, true, false);
    if (sax.tooDeep() || sax.failed() || !parsed) {
        int line = 1, column = 1;
        if (sax.tooDeep()) {
            // The depth limit stops the parser without a position; the
            // structure so far is of no use, so report it without one.
            errors.addGeneral("parse error: JSON nested deeper than " +
                              std::to_string(kMaxJsonDepth) + " levels");
            return false;
        }
        // nlohmann's position counts the bytes read, so it lies just past the
        // offending token, and its token text may include what came before.
        // Point at the character the lexer choked on inside an invalid token
        // ("last read: ..."), at the end of the text when it ended too early,
        // and otherwise at the start of the unexpected token.
        const std::string& message = sax.errorMessage();
        const size_t read = std::min(sax.errorPosition(), text.size());
        size_t position = read > 0 ? read - 1 : 0;
        if (message.find("unexpected end of input") != std::string::npos) {
            position = text.size();
        } else if (message.find("last read:") == std::string::npos) {
            position = tokenStart(text, position);
        }
        lineAndColumn(text, position, line, column);
        if (sax.errorId() == 406) {
            errors.addAt(
                line, column, sax.errorPath(),
                "number " + sax.errorToken() + " is out of range: must be a finite number");
        } else {
            errors.addAt(line, column, sax.errorPath(), reasonOf(sax.errorMessage()));
        }
        return false;
    }
    // Duplicate keys were reported; the document (holding the last value of
    // each) is still complete, so checking can go on and find more problems.
    return true;
}

JsonObjectReader::JsonObjectReader(const Json& value, std::string path, ErrorList& errors)
    : value_(&value), path_(std::move(path)), errors_(errors), ok_(value.is_object()) {
    if (!ok_) errors_.add(path_, "must be an object { ... }, got " + describe(value));
}

const Json* JsonObjectReader::find(const char* key) const {
    if (!ok_) return nullptr;
    const auto it = value_->find(key);
    return it == value_->end() ? nullptr : &*it;
}

bool JsonObjectReader::has(const char* key) const {
    return find(key) != nullptr;
}

bool JsonObjectReader::checkKeys(std::initializer_list<const char*> allowed,
                                 const std::string& context) {
    if (!ok_) return false;
    bool clean = true;
    for (auto it = value_->begin(); it != value_->end(); ++it) {
        bool known = false;
        for (const char* name : allowed) known = known || it.key() == name;
        if (known) continue;
        std::string list;
        for (const char* name : allowed) list += std::string(list.empty() ? "" : ", ") + name;
        errors_.add(pathOf(it.key()), "unknown key" + (context.empty() ? "" : " " + context) +
                                          " (allowed: " + list + ")");
        clean = false;
    }
    return clean;
}

bool JsonObjectReader::require(const char* key, const std::string& expected) {
    if (!ok_) return false;
    if (has(key)) return true;
    errors_.add(pathOf(key), "missing; must be " + expected);
    return false;
}

bool readNumberValue(const Json& value, const std::string& path, const NumberRule& rule,
                     ErrorList& errors, double& out) {
    if (!value.is_number()) {
        errors.add(path, std::string("must be ") + rule.expected + ", got " + describe(value));
        return false;
    }
    const double v = value.get<double>();
    if (!std::isfinite(v)) {
        errors.add(path, std::string("must be ") + rule.expected + ", got a non-finite number");
        return false;
    }
    if (std::abs(v) > kMaxMagnitude) {
        errors.add(path, "must be at most " + formatNumber(kMaxMagnitude) +
                             " in magnitude (the scene size limit), got " + describe(value));
        return false;
    }
    const bool below = rule.min_exclusive ? !(v > rule.min) : !(v >= rule.min);
    const bool above = rule.max_exclusive ? !(v < rule.max) : !(v <= rule.max);
    if (below || above) {
        errors.add(path, std::string("must be ") + rule.expected + ", got " + describe(value));
        return false;
    }
    out = v;
    return true;
}

bool JsonObjectReader::number(const char* key, bool required, const NumberRule& rule, double& out) {
    const Json* v = find(key);
    if (!v) return required ? require(key, rule.expected) : ok_;
    return readNumberValue(*v, pathOf(key), rule, errors_, out);
}

bool JsonObjectReader::integer(const char* key, bool required, int64_t min, int64_t max,
                               const std::string& expected, int64_t& out) {
    const Json* v = find(key);
    if (!v) return required ? require(key, expected) : ok_;
    bool fits = false;
    int64_t value = 0;
    if (v->is_number_unsigned()) {
        const uint64_t u = v->get<uint64_t>();
        fits = u <= uint64_t(INT64_MAX);
        value = fits ? int64_t(u) : 0;
    } else if (v->is_number_integer()) {
        value = v->get<int64_t>();
        fits = true;
    }
    if (!fits || value < min || value > max) {
        errors_.add(pathOf(key), "must be " + expected + ", got " + describe(*v));
        return false;
    }
    out = value;
    return true;
}

bool JsonObjectReader::unsignedInteger(const char* key, bool required, uint64_t& out) {
    static const std::string expected = "an integer in [0, 18446744073709551615]";
    const Json* v = find(key);
    if (!v) return required ? require(key, expected) : ok_;
    if (v->is_number_unsigned() || (v->is_number_integer() && v->get<int64_t>() >= 0)) {
        out = v->get<uint64_t>();
        return true;
    }
    errors_.add(pathOf(key), "must be " + expected + ", got " + describe(*v));
    return false;
}

bool JsonObjectReader::string(const char* key, bool required, std::string& out) {
    const Json* v = find(key);
    if (!v) return required ? require(key, "a string") : ok_;
    if (!v->is_string()) {
        errors_.add(pathOf(key), "must be a string, got " + describe(*v));
        return false;
    }
    out = v->get<std::string>();
    return true;
}

bool readVectorValue(const Json& value, const std::string& path, int count, ErrorList& errors,
                     glm::dvec3& out) {
    if (!value.is_array() || value.size() != size_t(count)) {
        errors.add(path,
                   "must be " + std::to_string(count) + " numbers [" +
                       (count == 2 ? "x, y] (the scene is 2D)" : "x, y, z] (the scene is 3D)") +
                       ", got " + describe(value));
        return false;
    }
    glm::dvec3 result{0.0};
    bool good = true;
    const NumberRule rule;
    for (int i = 0; i < count; ++i)
        good = readNumberValue(value[size_t(i)], indexPath(path, size_t(i)), rule, errors,
                               result[i]) &&
               good;
    if (good) out = result;
    return good;
}

bool JsonObjectReader::vector(const char* key, bool required, int count, glm::dvec3& out) {
    const Json* v = find(key);
    if (!v)
        return required ? require(key, std::to_string(count) + " numbers [" +
                                           (count == 2 ? "x, y]" : "x, y, z]"))
                        : ok_;
    return readVectorValue(*v, pathOf(key), count, errors_, out);
}

bool JsonObjectReader::range(const char* key, bool required, const NumberRule& rule, double& lo,
                             double& hi) {
    const std::string expected = std::string("[min, max], each ") + rule.expected;
    const Json* v = find(key);
    if (!v) return required ? require(key, expected) : ok_;
    const std::string path = pathOf(key);
    if (!v->is_array() || v->size() != 2) {
        errors_.add(path, "must be " + expected + ", got " + describe(*v));
        return false;
    }
    double a = 0.0, b = 0.0;
    const bool good_a = readNumberValue((*v)[0], indexPath(path, 0), rule, errors_, a);
    const bool good_b = readNumberValue((*v)[1], indexPath(path, 1), rule, errors_, b);
    if (!good_a || !good_b) return false;
    if (a > b) {
        errors_.add(path, "must be [min, max] with min <= max, got " + describe(*v));
        return false;
    }
    lo = a;
    hi = b;
    return true;
}

bool JsonObjectReader::integers(const char* key, bool required, int count, int64_t min, int64_t max,
                                const std::string& expected, int64_t* out) {
    const std::string whole = std::to_string(count) + " " + expected;
    const Json* v = find(key);
    if (!v) return required ? require(key, whole) : ok_;
    const std::string path = pathOf(key);
    if (!v->is_array() || v->size() != size_t(count)) {
        errors_.add(path, "must be " + whole + ", got " + describe(*v));
        return false;
    }
    bool good = true;
    for (int i = 0; i < count; ++i) {
        const Json& e = (*v)[size_t(i)];
        const bool integral = e.is_number_integer() || e.is_number_unsigned();
        const bool in_range =
            integral &&
            (e.is_number_unsigned() ? e.get<uint64_t>() <= uint64_t(max)
                                    : e.get<int64_t>() >= min && e.get<int64_t>() <= max);
        if (!in_range) {
            errors_.add(indexPath(path, size_t(i)), "must be " + expected + ", got " + describe(e));
            good = false;
            continue;
        }
        out[i] = e.get<int64_t>();
        if (out[i] < min) {
            errors_.add(indexPath(path, size_t(i)), "must be " + expected + ", got " + describe(e));
            good = false;
        }
    }
    return good;
}

}  // namespace gridcull
