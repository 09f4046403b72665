// JSON text and files, for every format built on JSON (scenes, lessons, a student's trace):
// a file read only when it is a regular file of bounded size, text parsed with errors that name
// line and column (depth and duplicate keys checked first), and typed access to values that names
// the JSON path (scene_json.h). The scene format itself is scene.cpp.
#include "scene_json.h"

#include "printable.h"
#include "safe_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <set>
#include <string_view>

using json = nlohmann::json;

namespace {

constexpr std::size_t kMaxFileBytes = 64u << 20; // 64 MiB
constexpr int kMaxDepth = 64;                    // the format itself needs 4 levels

// ---- Syntax: line and column, and a pre-scan for nesting depth and duplicate keys ----

struct TextPlace {
    std::size_t line = 1, column = 1;
};

TextPlace placeOf(const std::string& text, std::size_t index) {
    index = std::min(index, text.size());
    TextPlace place;
    for (std::size_t i = 0; i < index; ++i) {
        if (text[i] == '\n') {
            ++place.line;
            place.column = 1;
        } else {
            ++place.column;
        }
    }
    return place;
}

std::string placeName(const std::string& source, const std::string& text, std::size_t index) {
    const TextPlace p = placeOf(text, index);
    return source + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
}

struct ScanProblem {
    std::size_t index = 0;
    std::string message;
};

// Appends code point c as UTF-8 (a lone surrogate, which the parser has refused by now, as the
// replacement character).
void appendUtf8(std::string& out, std::uint32_t c) {
    if (c >= 0xd800 && c <= 0xdfff) c = 0xfffd;
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xc0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3f));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xe0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
        out += static_cast<char>(0x80 | (c & 0x3f));
    } else {
        out += static_cast<char>(0xf0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3f));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
        out += static_cast<char>(0x80 | (c & 0x3f));
    }
}

// The text of a JSON string that the parser has accepted (without its quotes), its escapes
// decoded: "m\u0061ss" and "mass" are the same key.
std::string decodedString(std::string_view raw) {
    std::string out;
    out.reserve(raw.size());
    auto hex4 = [&](std::size_t at) {
        std::uint32_t v = 0;
        for (std::size_t k = at; k < at + 4 && k < raw.size(); ++k) {
            const char c = raw[k];
            v = v * 16 + static_cast<std::uint32_t>(std::isdigit(static_cast<unsigned char>(c))
                                                        ? c - '0'
                                                        : (std::tolower(c) - 'a' + 10));
        }
        return v;
    };
    for (std::size_t i = 0; i < raw.size(); ++i) {
        if (raw[i] != '\\' || i + 1 >= raw.size()) {
            out += raw[i];
            continue;
        }
        const char e = raw[++i];
        if (e != 'u') {
            const char* const from = "bfnrt";
            const char* const to = "\b\f\n\r\t";
            const char* const at = std::strchr(from, e);
            out += at && *at ? to[at - from] : e; // \" \\ \/ stand for themselves
            continue;
        }
        std::uint32_t c = hex4(i + 1);
        i += 4;
        // A high surrogate followed by a low one: one code point beyond U+FFFF.
        if (c >= 0xd800 && c <= 0xdbff && i + 6 < raw.size() && raw[i + 1] == '\\' &&
            raw[i + 2] == 'u') {
            const std::uint32_t low = hex4(i + 3);
            if (low >= 0xdc00 && low <= 0xdfff) {
                c = 0x10000 + ((c - 0xd800) << 10) + (low - 0xdc00);
                i += 6;
            }
        }
        appendUtf8(out, c);
    }
    return out;
}

// Walks the text once without recursion. Finds nesting deeper than kMaxDepth (nlohmann's DOM is
// built and destroyed recursively, so a 100,000-deep "[[[[" must never reach it) and duplicate
// keys in one object (nlohmann would silently keep the last), compared after decoding their
// escapes. Strings are skipped with their escapes; anything malformed is left for the real
// parser to report.
std::optional<ScanProblem> prescan(const std::string& text, bool checkDuplicates) {
    std::vector<std::set<std::string>> keys; // one set per open object: decoded keys
    std::vector<char> open;                  // '{' or '['
    const std::string_view all(text);
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '{' || c == '[') {
            if (open.size() >= static_cast<std::size_t>(kMaxDepth))
                return ScanProblem{i,
                                   "nesting deeper than " + std::to_string(kMaxDepth) + " levels"};
            open.push_back(c);
            keys.emplace_back();
        } else if (c == '}' || c == ']') {
            if (!open.empty()) {
                open.pop_back();
                keys.pop_back();
            }
        } else if (c == '"') {
            const std::size_t start = i;
            for (++i; i < text.size() && text[i] != '"'; ++i)
                if (text[i] == '\\') ++i;
            if (!checkDuplicates || open.empty() || open.back() != '{') continue;
            std::size_t next = i + 1;
            while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next])))
                ++next;
            if (next >= text.size() || text[next] != ':') continue; // a value, not a key
            const std::string_view raw = all.substr(start + 1, i - start - 1);
            std::string key = decodedString(raw);
            if (keys.back().count(key)) {
                std::string message = "duplicate key \"" + printable(key) + "\"";
                if (key != raw) message += " (written \"" + printable(raw) + "\")";
                return ScanProblem{start, message};
            }
            keys.back().insert(std::move(key));
        }
    }
    return std::nullopt;
}

// nlohmann's messages start with "[json.exception...] parse error at line L, column C: " and may
// quote raw bytes of the input; those are shown as \xNN so junk never reaches a terminal.
std::string parserMessage(const std::string& what) {
    const std::size_t column = what.find("column ");
    const std::size_t colon = what.find(": ", column == std::string::npos ? 0 : column);
    const std::string message = colon == std::string::npos ? what : what.substr(colon + 2);
    return printable(message, 2 * kPrintableDefault);
}

} // namespace

// ---- Values: typed access that names the JSON path on failure (scene_json.h) ----

namespace scene_json {

std::string indexPath(const std::string& path, std::size_t i) {
    return path + "[" + std::to_string(i) + "]";
}
// The key is from the file: shown printable (an unknown key's name may be anything).
std::string keyPath(const std::string& path, const std::string& key) {
    const std::string shown = printable(key);
    return path.empty() ? shown : path + "." + shown;
}

void checkKeys(const json& object, const std::string& path,
               std::initializer_list<const char*> known) {
    checkKeys(object, path, std::vector<const char*>(known));
}

void checkKeys(const json& object, const std::string& path, const std::vector<const char*>& known) {
    for (const auto& item : object.items()) {
        const bool ok =
            std::any_of(known.begin(), known.end(), [&](const char* k) { return item.key() == k; });
        if (!ok) throw ValueError{keyPath(path, item.key()), "unknown key"};
    }
}

const json& requireObject(const json& value, const std::string& path) {
    if (!value.is_object()) throw ValueError{path, "must be an object"};
    return value;
}

double number(const json& value, const std::string& path) {
    if (!value.is_number()) throw ValueError{path, "must be a number"};
    const double x = value.get<double>();
    if (!std::isfinite(x)) throw ValueError{path, "must be a finite number"};
    return x;
}

std::string string(const json& value, const std::string& path) {
    if (!value.is_string()) throw ValueError{path, "must be a string"};
    return value.get<std::string>();
}

double number(const json& value, const std::string& path, const limits::Range& range) {
    const double x = number(value, path);
    if (std::string problem = limits::violation(range, x); !problem.empty())
        throw ValueError{path, problem};
    return x;
}

std::vector<double> numbers(const json& value, const std::string& path, std::size_t n,
                            const limits::Range& range) {
    if (!value.is_array() || value.size() != n)
        throw ValueError{path, "must be an array of " + std::to_string(n) + " numbers"};
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(number(value[i], indexPath(path, i), range));
    return out;
}

Vec2 vec2(const json& value, const std::string& path, const limits::Range& range) {
    const std::vector<double> v = numbers(value, path, 2, range);
    return {v[0], v[1]};
}

std::vector<double> numbers(const json& value, const std::string& path, std::size_t n) {
    return numbers(value, path, n, limits::kMagnitude);
}

Vec2 vec2(const json& value, const std::string& path) {
    return vec2(value, path, limits::kMagnitude);
}

} // namespace scene_json

std::optional<SceneError> parseJsonText(const std::string& text, const std::string& sourceName,
                                        json& root) {
    if (text.size() > kMaxFileBytes) return sceneError(sourceName, "larger than 64 MiB");
    if (std::all_of(text.begin(), text.end(),
                    [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }))
        return sceneError(placeName(sourceName, text, text.size()), "the file is empty");
    if (auto problem = prescan(text, false)) // depth first: the parser must never see it
        return sceneError(placeName(sourceName, text, problem->index), problem->message);
    try {
        root = json::parse(text);
    } catch (const json::parse_error& e) {
        const std::size_t index = e.byte > 0 ? e.byte - 1 : 0;
        return sceneError(placeName(sourceName, text, index), parserMessage(e.what()));
    } catch (const json::exception& e) {
        // Number overflow (1e400) has no position in nlohmann; find the number in the text.
        std::string message = e.what();
        const std::size_t quote = message.find('\'');
        std::size_t index = std::string::npos;
        if (quote != std::string::npos && message.back() == '\'')
            index = text.find(message.substr(quote + 1, message.size() - quote - 2));
        message =
            message.substr(message.find("] ") == std::string::npos ? 0 : message.find("] ") + 2);
        if (index == std::string::npos) return sceneError(sourceName, message);
        return sceneError(placeName(sourceName, text, index), message);
    }
    // The parser stops at a NUL byte as at the end of the text: junk after it would pass unseen.
    if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
        return sceneError(placeName(sourceName, text, nul), "a NUL byte: this is not a text file");
    if (auto problem = prescan(text, true))
        return sceneError(placeName(sourceName, text, problem->index), problem->message);
    return std::nullopt;
}

const std::vector<const char*> kSceneKeys = {"name",  "description", "duration",
                                             "world", "blocks",      "player"};

namespace {

// SAX events of nlohmann's parser (json::sax_parse) as the root object's keys and values:
// `visitor.rootKey(k)` hears each of the root's keys, `visitor.rootValue(s)` the value that
// follows (a string as `s`, anything else as nullptr); either stops the parse by returning false.
// A root that is not an object stops it at its first token. Builds nothing: deeper values are
// looked at only for their nesting.
template <class Visitor> struct RootObjectSax {
    Visitor& visitor;
    std::size_t depth = 0;

    bool scalar(const std::string* s) { return depth == 1 ? visitor.rootValue(s) : depth > 0; }
    bool null() { return scalar(nullptr); }
    bool boolean(bool) { return scalar(nullptr); }
    bool number_integer(json::number_integer_t) { return scalar(nullptr); }
    bool number_unsigned(json::number_unsigned_t) { return scalar(nullptr); }
    bool number_float(json::number_float_t, const json::string_t&) { return scalar(nullptr); }
    bool string(json::string_t& s) { return scalar(&s); }
    bool binary(json::binary_t&) { return scalar(nullptr); }
    bool start_object(std::size_t) { return open(); }
    bool start_array(std::size_t) { return depth > 0 && open(); } // an array root: no object
    bool open() {
        if (depth == 1 && !visitor.rootValue(nullptr)) return false;
        ++depth;
        return true;
    }
    bool key(json::string_t& k) { return depth != 1 || visitor.rootKey(k); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }
    bool close() {
        --depth;
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) {
        return false;
    }
};

// Whether the root has `wanted`: stops at it.
struct RootKeyFinder {
    const std::string& wanted;
    bool found = false;
    bool rootKey(const std::string& k) {
        found = k == wanted;
        return !found;
    }
    bool rootValue(const std::string*) { return true; }
};

// The root's string "name", while every root key is a scene's: stops at the first that is not,
// and at a "name" that is not a string.
struct SceneNameFinder {
    std::optional<std::string> name;
    std::string key;
    bool rootKey(const std::string& k) {
        key = k;
        return std::any_of(kSceneKeys.begin(), kSceneKeys.end(),
                           [&](const char* sceneKey) { return k == sceneKey; });
    }
    bool rootValue(const std::string* s) {
        if (key != "name") return true;
        if (s) name = *s;
        return s != nullptr;
    }
};

} // namespace

bool jsonRootHasKey(const std::string& text, const std::string& key) {
    RootKeyFinder finder{key};
    RootObjectSax<RootKeyFinder> sax{finder};
    json::sax_parse(text, &sax);
    if (!finder.found) return false; // no such key at the root, or it did not parse that far
    json root;
    return !parseJsonText(text, "", root);
}

std::optional<std::string> sceneNameOf(const std::string& text) {
    SceneNameFinder finder;
    RootObjectSax<SceneNameFinder> sax{finder};
    if (!json::sax_parse(text, &sax)) return std::nullopt;
    return finder.name;
}

std::optional<SceneError> regularFileError(const std::string& path) {
    // Only regular files: a directory cannot be read and a FIFO could block forever. A path that
    // cannot be followed says why (a symlink loop, a directory without permission).
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found)
        return sceneError(path, "no such file");
    if (ec) return sceneError(path, unfollowablePathWhy(ec));
    if (!std::filesystem::is_regular_file(status)) return sceneError(path, "not a regular file");
    return std::nullopt;
}

std::optional<SceneError> readJsonFile(const std::string& path, std::string& text) {
    if (auto error = regularFileError(path)) return error;
    std::ifstream in(path, std::ios::binary);
    if (!in) return sceneError(path, "cannot open the file");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) return sceneError(path, "cannot read the file");
    if (static_cast<std::uint64_t>(size) > kMaxFileBytes)
        return sceneError(path, "larger than 64 MiB");
    in.seekg(0, std::ios::beg);
    text.assign(static_cast<std::size_t>(size), '\0');
    if (size > 0 && !in.read(&text[0], size)) return sceneError(path, "cannot read the file");
    return std::nullopt;
}
