#include "equation_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace {

enum class Kind { Number, Name, Op, Relation, Break };

// Operators as one char each: + - * / ^ ( ) | and 'q' square, 'c' cube, 'r' root (√ or sqrt).
struct Token {
    Kind kind = Kind::Break;
    char op = 0;             // Op: the operator; Relation: '=', '<', '>', 'l' (<=), 'g' (>=)
    double value = 0.0;      // Number
    double unit = 1.0;       // Number: the value of one unit in its last printed digit
    bool scientific = false; // Number: written with an exponent ("1.5e+12")
    std::string name;        // Name
    std::size_t begin = 0;   // byte range in the text
    std::size_t end = 0;
};

bool startsWith(const std::string& s, std::size_t at, const char* prefix) {
    return s.compare(at, std::strlen(prefix), prefix) == 0;
}

// A UTF-8 sequence read as an operator or relation (`op` set, length returned), 0 if none.
std::size_t unicodeSymbol(const std::string& s, std::size_t at, Kind& kind, char& op) {
    static const struct {
        const char* bytes;
        Kind kind;
        char op;
    } symbols[] = {
        {"\u00b7", Kind::Op, '*'},       {"\u00d7", Kind::Op, '*'},       {"\u2212", Kind::Op, '-'},
        {"\u00b2", Kind::Op, 'q'},       {"\u00b3", Kind::Op, 'c'},       {"\u221a", Kind::Op, 'r'},
        {"\u2264", Kind::Relation, 'l'}, {"\u2265", Kind::Relation, 'g'},
    };
    for (const auto& sym : symbols) {
        if (startsWith(s, at, sym.bytes)) {
            kind = sym.kind;
            op = sym.op;
            return std::strlen(sym.bytes);
        }
    }
    return 0;
}

// Length of the UTF-8 sequence at `at` when it can be part of a name (letters such as µ, Δ, é),
// 0 when it is punctuation (dashes, quotes, ≈, no-break space, °).
std::size_t unicodeLetter(const std::string& s, std::size_t at) {
    const unsigned char c = static_cast<unsigned char>(s[at]);
    std::size_t length = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
    if (at + length > s.size()) return 0;
    if (c == 0xC2) return static_cast<unsigned char>(s[at + 1]) == 0xB5 ? 2 : 0; // µ only
    if (c >= 0xC3 && c <= 0xDF) return length; // Latin letters, Greek, Cyrillic
    return 0;                                  // symbols and punctuation
}

bool nameChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '\'';
}

// True when the line starting at `at` continues the chain of the line before: after its
// indentation it starts with an operator or a relation (a formula wrapped before an operator,
// wrapFormula: "p before = 1·3.594 + 1000000·0.99999354\n  = 999997.136"); a minus only with a
// space after it (binary; "-6" starts a line of its own).
bool continuesChain(const std::string& s, std::size_t at) {
    while (at < s.size() && s[at] == ' ') ++at;
    if (at >= s.size()) return false;
    if (std::strchr("=+*/<>", s[at])) return true;
    for (const char* op : {"\u00b7", "\u00d7", "\u2264", "\u2265"})
        if (startsWith(s, at, op)) return true;
    for (const char* minus : {"- ", "\u2212 "})
        if (startsWith(s, at, minus)) return true;
    return false;
}

std::vector<Token> tokenize(const std::string& s) {
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < s.size()) {
        const char c = s[i];
        Token t;
        t.begin = i;
        if (c == ' ' || c == '\t' || (c == '\n' && continuesChain(s, i + 1))) {
            ++i;
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c))) {
            std::size_t j = i;
            while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
            int decimals = 0;
            if (j + 1 < s.size() && s[j] == '.' &&
                std::isdigit(static_cast<unsigned char>(s[j + 1]))) {
                ++j;
                while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j])))
                    ++j, ++decimals;
            }
            int exponent = 0;
            if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
                std::size_t k = j + 1;
                if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
                if (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) {
                    while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
                    exponent = std::atoi(s.substr(j + 1, k - j - 1).c_str());
                    j = k;
                    t.scientific = true;
                }
            }
            t.kind = Kind::Number;
            t.value = std::strtod(s.substr(i, j - i).c_str(), nullptr);
            t.unit = std::pow(10.0, exponent - decimals);
            t.end = i = j;
            out.push_back(t);
            continue;
        }
        Kind kind;
        char op;
        if (const std::size_t n = unicodeSymbol(s, i, kind, op)) {
            t.kind = kind;
            t.op = op;
            t.end = i += n;
            out.push_back(t);
            continue;
        }
        const bool letter = std::isalpha(static_cast<unsigned char>(c)) || c == '_';
        if (letter || unicodeLetter(s, i)) {
            std::size_t j = i;
            while (j < s.size()) {
                if (nameChar(s[j])) {
                    ++j;
                } else if (const std::size_t n = (s[j] & 0x80) ? unicodeLetter(s, j) : 0) {
                    j += n;
                } else {
                    break;
                }
            }
            t.name = s.substr(i, j - i);
            t.end = i = j;
            if (t.name == "inf" || t.name == "nan") {
                t.kind = Kind::Number;
                t.value = t.name == "inf" ? std::numeric_limits<double>::infinity()
                                          : std::numeric_limits<double>::quiet_NaN();
            } else if (t.name == "sqrt") {
                t.kind = Kind::Op;
                t.op = 'r';
            } else {
                t.kind = Kind::Name;
            }
            out.push_back(t);
            continue;
        }
        const char next = i + 1 < s.size() ? s[i + 1] : '\0';
        if (c == '=' || c == '<' || c == '>') {
            t.kind = Kind::Relation;
            t.op = c;
            if (c != '=' && next == '=') {
                t.op = c == '<' ? 'l' : 'g';
                ++i;
            } else if (c == '=' && (next == '=' || next == '>')) {
                t.kind = Kind::Break; // "==", "=>": not an equation of this kind
                ++i;
            }
            t.end = ++i;
            out.push_back(t);
            continue;
        }
        if (std::strchr("+-*/^()|", c)) {
            t.kind = Kind::Op;
            t.op = c;
        }
        // Anything else (':', ',', ';', '.', '!', quotes, a multi-byte symbol) ends expressions.
        std::size_t n = 1;
        if (static_cast<unsigned char>(c) >= 0xC0) {
            n = static_cast<unsigned char>(c) >= 0xF0   ? 4
                : static_cast<unsigned char>(c) >= 0xE0 ? 3
                                                        : 2;
        }
        t.end = i = std::min(s.size(), i + n);
        out.push_back(t);
    }
    return out;
}

// One side's value as the parser reads it.
struct Side {
    bool ok = false;
    std::size_t end = 0; // the token after it
    double value = 0.0;
    bool named = false;      // it has a name: a label, not evaluated
    bool literal = false;    // a plain number: 2, -0.5, (-2)
    double unit = 1.0;       // a literal's last printed digit's unit
    bool scientific = false; // a literal written with an exponent
};

class Parser {
  public:
    explicit Parser(const std::vector<Token>& tokens) : t_(tokens) {}

    // The longest expression starting at token i (ok false when none): terms joined by + -.
    Side expression(std::size_t i) const { return leftToRight(i, &Parser::term, '+', '-'); }

    // A unit after a number (m, kg·m/s, m/s²): the token after it, or i when there is none.
    std::size_t skipUnit(std::size_t i) const {
        if (!isUnit(i)) return i;
        std::size_t j = i + 1;
        while (j < t_.size()) {
            if (isOp(j, 'q', 'c')) {
                ++j;
            } else if (isOp(j, '/', '*') && isUnit(j + 1)) {
                j += 2;
            } else {
                break;
            }
        }
        return j;
    }

    // True when the expression starting at token i would be the end of a longer one on its left
    // that did not parse (a function's call, the right operand of an operator).
    bool continuesLeft(std::size_t i) const {
        if (i == 0) return false;
        auto operandEnd = [&](std::size_t k) {
            return t_[k].kind == Kind::Number || t_[k].kind == Kind::Name || isOp(k, ')');
        };
        const std::size_t before = i - 1;
        if (isOp(before, '*', '/') || isOp(before, '^') || isOp(before, 'q', 'c')) return true;
        if (isOp(before, '+', '-') && before > 0 && operandEnd(before - 1)) return true;
        return operandEnd(before) && (isOp(i, '(') || isOp(i, '-', '+'));
    }

  private:
    bool isOp(std::size_t i, char a, char b = 0) const {
        return i < t_.size() && t_[i].kind == Kind::Op && (t_[i].op == a || (b && t_[i].op == b));
    }
    bool isUnit(std::size_t i) const {
        static const char* const units[] = {"m", "cm", "mm", "km", "s",  "ms",  "kg", "g",
                                            "J", "N",  "Hz", "W",  "px", "fps", "Pa"};
        if (i >= t_.size() || t_[i].kind != Kind::Name) return false;
        for (const char* u : units)
            if (t_[i].name == u) return true;
        return false;
    }

    static Side combine(Side a, const Side& b, char op) {
        a.end = b.end;
        a.named = a.named || b.named;
        a.literal = false;
        switch (op) {
        case '+':
            a.value += b.value;
            break;
        case '-':
            a.value -= b.value;
            break;
        case '*':
            a.value *= b.value;
            break;
        case '/':
            a.value /= b.value;
            break;
        default: // '^'
            a.value = std::pow(a.value, b.value);
            break;
        }
        return a;
    }

    // Operands read by `operand` and joined by the operators `a` and `b`, evaluated left to
    // right (a - b - c is (a - b) - c); it stops before an operator whose right operand does not
    // parse.
    Side leftToRight(std::size_t i, Side (Parser::*operand)(std::size_t) const, char a,
                     char b) const {
        Side left = (this->*operand)(i);
        while (left.ok && isOp(left.end, a, b)) {
            const Side right = (this->*operand)(left.end + 1);
            if (!right.ok) break;
            left = combine(left, right, t_[left.end].op);
        }
        return left;
    }

    // Factors joined by * /.
    Side term(std::size_t i) const { return leftToRight(i, &Parser::unary, '*', '/'); }

    Side unary(std::size_t i) const {
        if (isOp(i, '-', '+')) {
            Side s = unary(i + 1);
            if (s.ok && t_[i].op == '-') s.value = -s.value;
            return s;
        }
        return power(i);
    }

    Side power(std::size_t i) const {
        Side base = primary(i);
        while (base.ok) {
            if (isOp(base.end, 'q', 'c')) {
                base.value = std::pow(base.value, t_[base.end].op == 'q' ? 2.0 : 3.0);
                base.literal = false;
                ++base.end;
            } else if (isOp(base.end, '^')) {
                const Side exponent = unary(base.end + 1);
                if (!exponent.ok) break;
                base = combine(base, exponent, '^');
            } else {
                break;
            }
        }
        return base;
    }

    Side primary(std::size_t i) const {
        Side s;
        if (i >= t_.size()) return s;
        const Token& k = t_[i];
        if (k.kind == Kind::Number) {
            s.ok = s.literal = true;
            s.value = k.value;
            s.unit = k.unit;
            s.scientific = k.scientific;
            s.end = i + 1;
        } else if (k.kind == Kind::Name) {
            s.ok = s.named = true;
            s.value = std::numeric_limits<double>::quiet_NaN();
            s.end = i + 1;
        } else if (isOp(i, '(')) {
            s = expression(i + 1);
            if (!s.ok || !isOp(s.end, ')')) return Side{};
            ++s.end;
        } else if (isOp(i, '|')) {
            s = expression(i + 1);
            if (!s.ok || !isOp(s.end, '|')) return Side{};
            ++s.end;
            s.value = std::abs(s.value);
            s.literal = false;
        } else if (isOp(i, 'r')) {
            s = isOp(i + 1, '(') ? primary(i + 1) : power(i + 1);
            if (!s.ok) return Side{};
            s.value = std::sqrt(s.value);
            s.literal = false;
        }
        return s;
    }

    const std::vector<Token>& t_;
};

std::string fmt(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}

// One side of a chain: its text and what the parser read.
struct ChainSide {
    Side side;
    std::size_t first = 0; // token range
    std::size_t last = 0;
};

void checkChain(const std::string& text, const std::vector<Token>& tokens,
                const std::vector<ChainSide>& sides, const std::vector<char>& relations,
                double roundedTo, EquationReport& report) {
    // A literal's unit: its last printed digit's, or finer when the writer dropped zeros.
    auto unitOf = [&](const Side& s) {
        return roundedTo > 0.0 && !s.scientific ? std::min(s.unit, roundedTo) : s.unit;
    };
    auto sideText = [&](const ChainSide& c) {
        return text.substr(tokens[c.first].begin, tokens[c.last - 1].end - tokens[c.first].begin);
    };
    const std::string chain =
        text.substr(tokens[sides.front().first].begin,
                    tokens[sides.back().last - 1].end - tokens[sides.front().first].begin);
    auto problem = [&](const std::string& why) { report.problems.push_back({chain, why}); };
    // Groups of sides joined by '='; each group's printed value (NaN: unknown).
    std::vector<double> groupValue;
    std::size_t start = 0;
    for (std::size_t g = 0; g <= relations.size(); ++g) {
        if (g < relations.size() && relations[g] == '=') continue;
        // Sides start..g form one group. Its result: the last plain number in it.
        int result = -1;
        for (std::size_t k = start; k <= g; ++k)
            if (sides[k].side.literal) result = static_cast<int>(k);
        int reference = result;
        if (reference < 0)
            for (std::size_t k = start; k <= g; ++k)
                if (!sides[k].side.named) reference = static_cast<int>(k);
        double value = std::numeric_limits<double>::quiet_NaN();
        if (reference >= 0) {
            const Side& ref = sides[static_cast<std::size_t>(reference)].side;
            value = ref.value;
            for (std::size_t k = start; k <= g; ++k) {
                const Side& s = sides[k].side;
                if (s.named || static_cast<int>(k) == reference) continue;
                ++report.checked;
                if (!std::isfinite(s.value) || !std::isfinite(ref.value)) {
                    problem(sideText(sides[k]) + " is " + fmt(s.value) + ": not a number to check");
                    continue;
                }
                // Half a unit of the result's last printed digit (of the coarser, when both
                // sides are plain numbers); no result printed: the two must agree to 1e-9.
                double tolerance = result >= 0 ? 0.5 * unitOf(ref) : 1e-9 * std::abs(ref.value);
                if (s.literal) tolerance = std::max(tolerance, 0.5 * unitOf(s));
                tolerance *= 1.0 + 1e-9;
                if (!(std::abs(s.value - ref.value) <= tolerance)) {
                    problem(sideText(sides[k]) + " is " + fmt(s.value) + ", not " +
                            sideText(sides[static_cast<std::size_t>(reference)]) + " (to +-" +
                            fmt(tolerance) + ")");
                }
            }
        }
        groupValue.push_back(value);
        start = g + 1;
    }
    // The comparisons between groups, with the printed values.
    std::size_t group = 0;
    for (char rel : relations) {
        if (rel == '=') continue;
        const double a = groupValue[group], b = groupValue[group + 1];
        ++group;
        if (std::isnan(a) || std::isnan(b)) continue;
        ++report.checked;
        const bool holds = rel == '<' ? a < b : rel == '>' ? a > b : rel == 'l' ? a <= b : a >= b;
        if (!holds) {
            const char* name = rel == '<' ? "<" : rel == '>' ? ">" : rel == 'l' ? "<=" : ">=";
            problem(fmt(a) + " " + name + " " + fmt(b) + " is false");
        }
    }
}

} // namespace

EquationReport checkEquations(const std::string& text, double roundedTo) {
    EquationReport report;
    const std::vector<Token> tokens = tokenize(text);
    const Parser parser(tokens);
    std::size_t pos = 0;
    while (pos < tokens.size()) {
        std::size_t r = pos;
        while (r < tokens.size() && tokens[r].kind != Kind::Relation) ++r;
        if (r >= tokens.size()) break;
        // The left side: the longest run of tokens before the relation that is an expression.
        std::vector<ChainSide> sides;
        for (std::size_t s = pos; s < r; ++s) {
            if (parser.continuesLeft(s)) continue; // "ceil(x) - 1 = 3": not "-1 = 3"
            const Side left = parser.expression(s);
            if (left.ok && left.end == r) {
                sides.push_back({left, s, r});
                break;
            }
        }
        if (sides.empty()) {
            pos = r + 1;
            continue;
        }
        std::vector<char> relations;
        std::size_t at = r;
        while (at < tokens.size() && tokens[at].kind == Kind::Relation) {
            const Side right = parser.expression(at + 1);
            if (!right.ok) break;
            relations.push_back(tokens[at].op);
            sides.push_back({right, at + 1, right.end});
            at = right.named ? right.end : parser.skipUnit(right.end);
        }
        if (!relations.empty()) checkChain(text, tokens, sides, relations, roundedTo, report);
        pos = std::max(at, r + 1);
    }
    return report;
}

bool equationsHold(const std::string& text, double roundedTo) {
    return checkEquations(text, roundedTo).holds();
}
