#include "text_format.h"

#include "number_text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

bool isRoundingNoise(double value, double scale) {
    if (!std::isfinite(value)) return false;
    const double s = std::isfinite(scale) ? std::max(std::abs(scale), 1.0) : 1.0;
    return std::abs(value) <= kNoiseRelative * s;
}

std::string formatNumber(double value, double scale) {
    return formatNumberWithDigits(value, 0, scale);
}

std::string formatNumberWithDigits(double value, int extra, double scale) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    if (isRoundingNoise(value, scale)) return "0";
    char text[64];
    const double a = std::abs(value);
    const int digits = 3 + std::max(extra, 0);
    // (printf's "%.*g" and "%.*f", without printf: number_text.h)
    if (a >= 1e12) {
        number_text::printGeneral(text, sizeof text, value, digits);
        return text;
    }
    if (a < 5e-4) {
        number_text::printGeneral(text, sizeof text, value, digits);
        std::string s = text;
        // "%.3g" writes 1.23e-05 below 1e-4; a fixed form reads better down to 1e-6.
        if (a >= 1e-6 && s.find('e') != std::string::npos) {
            number_text::printFixed(text, sizeof text, value,
                                    (a >= 1e-5 ? 7 : 8) + std::max(extra, 0));
            s = text;
            while (!s.empty() && s.back() == '0') s.pop_back();
        }
        return s;
    }
    number_text::printFixed(text, sizeof text, value, digits);
    std::string s = text;
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    if (s == "-0") s = "0";
    return s;
}

std::string operand(double value, int extra) {
    const std::string s = formatNumberWithDigits(value, extra);
    return !s.empty() && s[0] == '-' ? "(" + s + ")" : s;
}

std::string formatQuantity(double value, const char* unit) {
    return formatNumber(value) + " " + unit;
}

namespace {

std::string trimmed(const std::string& s) {
    std::size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

// True when `text` ends in the unit g (grams), not kg.
bool inGrams(const std::string& text) {
    const std::string t = trimmed(text);
    return t.size() >= 2 && t.back() == 'g' && t[t.size() - 2] != 'k';
}

// True when `text` is a number followed by "kg" or "g" (spaces allowed around both): "4 kg",
// "50 g" (the feather's).
bool isMassText(const std::string& text) {
    const std::string t = trimmed(text);
    const std::size_t unit = inGrams(t) ? 1 : 2;
    if (t.size() < unit + 1 || t.compare(t.size() - unit, unit, unit == 1 ? "g" : "kg") != 0)
        return false;
    const std::string number = trimmed(t.substr(0, t.size() - unit));
    if (number.empty()) return false;
    char* end = nullptr;
    std::strtod(number.c_str(), &end);
    return end && *end == '\0';
}

// Where the mass part of `name` starts ("m1 = 1 kg": at " = "; "A (2 kg)": at " ("; "big ship,
// 4 kg": at ","), or npos.
std::size_t massPart(const std::string& name) {
    const std::size_t eq = name.rfind('=');
    if (eq != std::string::npos && eq > 0 && isMassText(name.substr(eq + 1))) return eq;
    const std::size_t comma = name.rfind(',');
    if (comma != std::string::npos && comma > 0 && isMassText(name.substr(comma + 1))) return comma;
    const std::size_t open = name.rfind('(');
    if (open != std::string::npos && open > 0 && !name.empty() && name.back() == ')' &&
        isMassText(name.substr(open + 1, name.size() - open - 2))) {
        return open;
    }
    return std::string::npos;
}

} // namespace

std::string baseBlockName(const std::string& name) {
    const std::size_t at = massPart(name);
    return at == std::string::npos ? name : trimmed(name.substr(0, at));
}

bool nameStatesMass(const std::string& name) {
    return massPart(name) != std::string::npos;
}

std::string nameWithMass(const std::string& name, double mass) {
    const std::size_t at = massPart(name);
    if (at == std::string::npos) return name;
    const std::string base = trimmed(name.substr(0, at));
    // In the unit the name states it in: "feather, 50 g" stays in grams.
    const bool grams =
        inGrams(name[at] == '(' ? name.substr(at + 1, name.size() - at - 2) : name.substr(at + 1));
    const std::string m = !std::isfinite(mass) ? "infinite mass"
                          : grams              ? formatNumber(mass * 1000.0) + " g"
                                               : formatNumber(mass) + " kg";
    if (name[at] == ',') return base + ", " + m;
    return name[at] == '=' ? base + " = " + m : base + " (" + m + ")";
}

std::string formulaSymbol(const std::string& name) {
    const std::string base = baseBlockName(name);
    if (base.empty() || base.size() > 3) return "";
    for (char c : base) {
        if (!std::isalnum(static_cast<unsigned char>(c))) return "";
    }
    // "m1" is already a mass symbol: its bodies' symbols are m1 and v1.
    if (base.size() >= 2 && base[0] == 'm' && std::isdigit(static_cast<unsigned char>(base[1])))
        return base.substr(1);
    return base;
}

namespace {

// One paragraph (no newline) into `out`, lines joined by '\n'.
void wrapParagraph(const std::string& text, double width,
                   const std::function<double(const std::string&)>& measure, std::string& out) {
    std::string line;
    auto flush = [&] {
        out += line;
        out += '\n';
        line.clear();
    };
    std::size_t i = 0;
    while (i <= text.size()) {
        const std::size_t end = std::min(text.find(' ', i), text.size());
        std::string word = text.substr(i, end - i);
        i = end + 1;
        if (!line.empty() && measure(line + " " + word) <= width) {
            line += " " + word;
            continue;
        }
        if (!line.empty()) flush();
        // A word wider than the line: as many characters (whole UTF-8 sequences) as fit.
        while (measure(word) > width && word.size() > 1) {
            std::size_t cut = 1;
            while (cut < word.size()) {
                std::size_t next = cut + 1;
                while (next < word.size() &&
                       (static_cast<unsigned char>(word[next]) & 0xC0) == 0x80)
                    ++next;
                if (measure(word.substr(0, next)) > width) break;
                cut = next;
            }
            while (cut < word.size() && (static_cast<unsigned char>(word[cut]) & 0xC0) == 0x80)
                ++cut;
            line = word.substr(0, cut);
            word = word.substr(cut);
            flush();
        }
        line = word;
    }
    out += line;
}

using WrapParagraph = void (*)(const std::string&, double,
                               const std::function<double(const std::string&)>&, std::string&);

// Each paragraph of `text` (its own newlines kept) wrapped by `wrap`.
std::string wrapParagraphs(const std::string& text, double width,
                           const std::function<double(const std::string&)>& measure,
                           WrapParagraph wrap) {
    std::string out;
    std::size_t start = 0;
    while (true) {
        const std::size_t newline = text.find('\n', start);
        wrap(text.substr(start, newline == std::string::npos ? std::string::npos : newline - start),
             width, measure, out);
        if (newline == std::string::npos) break;
        out += '\n';
        start = newline + 1;
    }
    return out;
}

} // namespace

std::string wrapAtSpaces(const std::string& text, double width,
                         const std::function<double(const std::string&)>& measure) {
    return wrapParagraphs(text, width, measure, wrapParagraph);
}

std::string wrapAtSeparators(const std::string& text, const std::string& separator, double width,
                             const std::function<double(const std::string&)>& measure) {
    if (separator.empty()) return wrapAtSpaces(text, width, measure);
    std::string out, line;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(separator, start), text.size());
        const std::string part = text.substr(start, end - start);
        const std::string joined = line.empty() ? part : line + separator + part;
        if (line.empty() || measure(joined) <= width) {
            line = joined;
        } else {
            out += line + "\n";
            line = part;
        }
        start = end + separator.size();
    }
    return wrapAtSpaces(out + line, width, measure);
}

namespace {

bool isOperatorWord(const std::string& w) {
    static const char* const ops[] = {"=",  "+",  "-",      "*",      "/",      "<",      ">",
                                      "<=", ">=", "\u2212", "\u00b7", "\u00d7", "\u2264", "\u2265"};
    for (const char* op : ops)
        if (w == op) return true;
    return false;
}

bool isRelationWord(const std::string& w) {
    static const char* const relations[] = {"=", "<", ">", "<=", ">=", "\u2264", "\u2265"};
    for (const char* r : relations)
        if (w == r) return true;
    return false;
}

// The words of `text` between `from` and `to` (a line), indented when it continues a formula;
// the spaces of a gap at its end (a line broken before an aside) left out. A glued word is the
// rest of a word broken inside (innerPieces): no space before it on a line.
std::string lineOf(const std::vector<std::string>& words, const std::vector<bool>& glued,
                   std::size_t from, std::size_t to) {
    while (to > from + 1 && words[to - 1].empty()) --to;
    std::string line = from > 0 && (isOperatorWord(words[from]) || glued[from]) ? "  " : "";
    for (std::size_t k = from; k < to; ++k) line += (k > from && !glued[k] ? " " : "") + words[k];
    return line;
}

// A word wider than a line (a quotient or a product of long numbers:
// "1000000·0.99999873006)/(1") in pieces: broken before each '/' that stands between ')' and '(',
// and with `atProducts` before each '·' of a product of numbers too. Each piece after the first
// starts with its operator, as a line wrapped before an operator does, so the chain reads on
// (equation_check.h).
std::vector<std::string> innerPieces(const std::string& word, bool atProducts) {
    static const std::string kDot = "\u00b7";
    std::vector<std::string> pieces;
    std::size_t start = 0;
    for (std::size_t i = 1; i < word.size(); ++i) {
        // A product of numbers ("1000000·0.99999873006"), not a unit's ("kg·m/s").
        const std::size_t next = i + kDot.size();
        const bool product = atProducts && word.compare(i, kDot.size(), kDot) == 0 &&
                             next < word.size() &&
                             (std::isdigit(static_cast<unsigned char>(word[next])) ||
                              word[next] == '(' || word[next] == '-');
        const bool quotient =
            word[i] == '/' && word[i - 1] == ')' && i + 1 < word.size() && word[i + 1] == '(';
        if (!product && !quotient) continue;
        pieces.push_back(word.substr(start, i - start));
        start = i;
    }
    pieces.push_back(word.substr(start));
    return pieces;
}

void wrapFormulaParagraph(const std::string& text, double width,
                          const std::function<double(const std::string&)>& measure,
                          std::string& out) {
    std::vector<std::string> words;
    for (std::size_t i = 0;;) {
        const std::size_t end = std::min(text.find(' ', i), text.size());
        words.push_back(text.substr(i, end - i));
        if (end >= text.size()) break;
        i = end + 1;
    }
    // A word that overflows a line of its own, with the operators before it that a line holds
    // ("  + 1000000·0.99999873006)/(1" in a narrow window), is broken inside, between its
    // factors (innerPieces), rather than be cut at the window's edge; never inside a number.
    // At its quotients first, and only a piece still too wide at its products.
    std::vector<bool> glued(words.size(), false);
    for (const bool atProducts : {false, true}) {
        for (std::size_t k = 0; k < words.size(); ++k) {
            std::size_t first = k;
            while (first > 0 && isOperatorWord(words[first - 1])) --first;
            if (measure(lineOf(words, glued, first, k + 1)) <= width) continue;
            const std::vector<std::string> pieces = innerPieces(words[k], atProducts);
            if (pieces.size() < 2) continue;
            const auto at = static_cast<std::ptrdiff_t>(k);
            words.erase(words.begin() + at);
            words.insert(words.begin() + at, pieces.begin(), pieces.end());
            glued.insert(glued.begin() + at + 1, pieces.size() - 1, true);
            k += pieces.size() - 1;
        }
    }
    // Word k continues a short group in parentheses opened by an earlier word (a vector
    // "(6, 0)", a pair): at most kGroupWords words from '(' to ')', read as one where the group
    // fits on a line.
    constexpr std::size_t kGroupWords = 3;
    std::vector<bool> inGroup(words.size(), false);
    // Word k opens such a group that fits on a line alone but not with the operators before it
    // ("= (20.052, -17.339)" in a narrow window): a line may start at it, after the operator,
    // rather than the group be split or overflow its window.
    std::vector<bool> groupOnItsOwn(words.size(), false);
    for (std::size_t k = 0; k < words.size(); ++k) {
        if (words[k].find('(') == std::string::npos || words[k].find(')') != std::string::npos)
            continue;
        for (std::size_t e = k + 1; e < words.size() && e < k + kGroupWords; ++e) {
            if (words[e].find('(') != std::string::npos) break;
            if (words[e].find(')') == std::string::npos) continue;
            if (measure(lineOf(words, glued, k, e + 1)) > width) break;
            // The line holding the group also holds the operators before it ("= (6, 0)").
            std::size_t first = k;
            while (first > 0 && isOperatorWord(words[first - 1])) --first;
            groupOnItsOwn[k] = measure(lineOf(words, glued, first, e + 1)) > width;
            // After an arithmetic operator ("0.99999932376 - 1·(1.5937 - 0.99999932376)") a
            // line starting at the group would leave its operator at the end of the line before
            // and the chain unreadable: the group is wrapped as the rest of the formula is.
            if (groupOnItsOwn[k] && !isRelationWord(words[k - 1])) {
                groupOnItsOwn[k] = false;
                break;
            }
            for (std::size_t j = k + 1; j <= e; ++j) inGroup[j] = true;
            break;
        }
    }
    // A short relation, one word on each side of its operator ("C = 1", "m1 = 1,"), is not
    // split where it fits on a line: "Here / C = 1" rather than "Here C / = 1". A chain
    // ("a = b = c", "x + y = 3") and a vector's group are left to the rules above and below.
    const auto isOperatorAt = [&](std::size_t k) {
        return k < words.size() && isOperatorWord(words[k]);
    };
    for (std::size_t k = 1; k + 1 < words.size(); ++k) {
        if (!isOperatorWord(words[k]) || words[k - 1].empty() || words[k + 1].empty()) continue;
        if (isOperatorAt(k - 1) || isOperatorAt(k + 1) || (k >= 2 && isOperatorAt(k - 2)) ||
            isOperatorAt(k + 2) || words[k + 1].find('(') != std::string::npos)
            continue;
        if (measure(lineOf(words, glued, k - 1, k + 2)) > width) continue;
        inGroup[k] = inGroup[k + 1] = true;
    }
    // A line may start at word k when k is not empty (the spaces of a gap stay together), the
    // word before is not an operator (unless k opens a group that fits only on its own) and k
    // is not inside a short group in parentheses. So a line may start after a gap of spaces, at
    // an aside ("v2' = v2 = 0   (infinite mass: unchanged)"): the aside goes under the equation
    // rather than run past the window's edge; the gap's spaces end no line.
    const auto canStart = [&](std::size_t k) {
        return k > 0 && !words[k].empty() && (!isOperatorWord(words[k - 1]) || groupOnItsOwn[k]) &&
               !inGroup[k];
    };
    std::vector<std::size_t> starts{0};
    while (true) {
        const std::size_t from = starts.back();
        // The last break that fits; the last one between two clauses (after a word ending in
        // ',', ':' or ';': "v1 = 6, | v2 = 0") instead when that keeps half the line.
        std::size_t next = words.size(), first = words.size(), clause = words.size();
        for (std::size_t k = from + 1; k < words.size(); ++k) {
            if (!canStart(k)) continue;
            if (first == words.size()) first = k;
            if (measure(lineOf(words, glued, from, k)) > width) break;
            next = k; // the line [from, k) fits: break there unless a later one does too
            if (!words[k - 1].empty() && std::strchr(",:;", words[k - 1].back())) clause = k;
        }
        if (measure(lineOf(words, glued, from, words.size())) <= width) break;
        if (clause != words.size() && measure(lineOf(words, glued, from, clause)) >= 0.5 * width)
            next = clause;
        if (next == words.size()) next = first; // nothing fits: the shortest piece overflows
        if (next == words.size()) break;
        starts.push_back(next);
    }
    // One word alone on the last line: the line before gives it its last piece, if that fits.
    if (starts.size() >= 2 && starts.back() + 1 == words.size()) {
        const std::size_t before = starts[starts.size() - 2];
        for (std::size_t k = starts.back() - 1; k > before; --k) {
            if (!canStart(k)) continue;
            if (measure(lineOf(words, glued, k, words.size())) <= width) starts.back() = k;
            break;
        }
    }
    for (std::size_t i = 0; i < starts.size(); ++i) {
        if (i > 0) out += '\n';
        out +=
            lineOf(words, glued, starts[i], i + 1 < starts.size() ? starts[i + 1] : words.size());
    }
}

} // namespace

std::string wrapFormula(const std::string& text, double width,
                        const std::function<double(const std::string&)>& measure) {
    return wrapParagraphs(text, width, measure, wrapFormulaParagraph);
}

bool saysWord(const std::string& text, const std::string& word) {
    if (word.empty()) return false;
    const auto inWord = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
        const std::size_t end = at + word.size();
        if ((at == 0 || !inWord(text[at - 1])) && (end == text.size() || !inWord(text[end])))
            return true;
    }
    return false;
}
