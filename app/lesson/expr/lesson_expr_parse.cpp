// Reading an expression (lesson_expr.h): a tokenizer and a recursive-descent parser whose every
// name is resolved against the step's scene and values when the lesson loads, with its depth and
// size bounded, so any text gives a tree or an error at its column.
#include "lesson_expr.h"

#include "printable.h"
#include "scene_json.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

using scene_json::ValueError;

namespace {

using Node = LessonExpr::Node;
using Kind = Node::Kind;

// Deeper nesting than this is refused: a hostile "((((...))))" never exhausts the stack.
constexpr int kMaxDepth = 48;
constexpr std::size_t kMaxNodes = 400;

bool isIdentStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool isIdentChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

struct Token {
    enum class Type { End, Number, Ident, Quoted, Op };
    Type type = Type::End;
    std::string text;
    std::size_t column = 0; // 1-based
};

class Parser {
  public:
    Parser(const std::string& text, const Scene& scene, const std::vector<std::string>& values,
           const std::string& path, std::size_t columnOffset)
        : text_(text), scene_(scene), values_(values), path_(path), offset_(columnOffset) {
        next();
    }

    LessonExpr parse(bool condition) {
        LessonExpr e;
        e.source = text_;
        expr_ = &e;
        e.root = parseOr(0);
        if (token_.type != Token::Type::End) fail(token_.column, "unexpected " + describe(token_));
        e.condition = isCondition(e.root);
        if (condition && !e.condition)
            fail(1, "must be a condition (a comparison such as m1.vx == -C*m1.vx0, joined by "
                    "and, or)");
        if (!condition && e.condition) fail(1, "must be a number, not a condition");
        return e;
    }

  private:
    const std::string& text_;
    const Scene& scene_;
    const std::vector<std::string>& values_;
    const std::string& path_;
    std::size_t offset_ = 0;
    std::size_t at_ = 0;
    Token token_;
    LessonExpr* expr_ = nullptr;

    [[noreturn]] void fail(std::size_t column, const std::string& why) const {
        // Columns count characters (a UTF-8 sequence is one), from 1.
        std::size_t characters = 1;
        for (std::size_t i = 0; i + 1 < column && i < text_.size(); ++i)
            if ((static_cast<unsigned char>(text_[i]) & 0xc0) != 0x80) ++characters;
        throw ValueError{path_, "column " + std::to_string(characters + offset_) + ": " + why};
    }

    static std::string describe(const Token& t) {
        if (t.type == Token::Type::End) return "end of the expression";
        return "\"" + printable(t.text) + "\"";
    }

    void next() {
        while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t')) ++at_;
        token_ = Token{};
        token_.column = at_ + 1;
        if (at_ >= text_.size()) return;
        const char c = text_[at_];
        if (std::isdigit(static_cast<unsigned char>(c)) ||
            (c == '.' && at_ + 1 < text_.size() &&
             std::isdigit(static_cast<unsigned char>(text_[at_ + 1])))) {
            std::size_t end = at_;
            while (end < text_.size() &&
                   (std::isdigit(static_cast<unsigned char>(text_[end])) || text_[end] == '.'))
                ++end;
            if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
                std::size_t exp = end + 1;
                if (exp < text_.size() && (text_[exp] == '+' || text_[exp] == '-')) ++exp;
                if (exp < text_.size() && std::isdigit(static_cast<unsigned char>(text_[exp]))) {
                    end = exp;
                    while (end < text_.size() &&
                           std::isdigit(static_cast<unsigned char>(text_[end])))
                        ++end;
                }
            }
            token_.type = Token::Type::Number;
            token_.text = text_.substr(at_, end - at_);
            at_ = end;
            return;
        }
        if (isIdentStart(c)) {
            std::size_t end = at_;
            while (end < text_.size() && isIdentChar(text_[end])) ++end;
            token_.type = Token::Type::Ident;
            token_.text = text_.substr(at_, end - at_);
            at_ = end;
            return;
        }
        if (c == '\'') {
            const std::size_t close = text_.find('\'', at_ + 1);
            if (close == std::string::npos) fail(at_ + 1, "a quoted block name has no closing '");
            token_.type = Token::Type::Quoted;
            token_.text = text_.substr(at_ + 1, close - at_ - 1);
            at_ = close + 1;
            return;
        }
        for (const char* op : {"==", "!=", "<=", ">="}) {
            if (text_.compare(at_, 2, op) == 0) {
                token_.type = Token::Type::Op;
                token_.text = op;
                at_ += 2;
                return;
            }
        }
        if (std::string("+-*/^(),.<>").find(c) != std::string::npos) {
            token_.type = Token::Type::Op;
            token_.text = std::string(1, c);
            ++at_;
            return;
        }
        fail(at_ + 1, "unexpected character \"" + printable(std::string(1, c)) + "\"");
    }

    bool isOp(const char* op) const { return token_.type == Token::Type::Op && token_.text == op; }
    bool isWord(const char* w) const {
        return token_.type == Token::Type::Ident && token_.text == w;
    }
    void expectOp(const char* op) {
        if (!isOp(op))
            fail(token_.column, std::string("expected \"") + op + "\", found " + describe(token_));
        next();
    }

    int add(Node n) {
        if (expr_->nodes.size() >= kMaxNodes) fail(token_.column, "too long an expression");
        expr_->nodes.push_back(std::move(n));
        return static_cast<int>(expr_->nodes.size()) - 1;
    }
    int node(Kind kind, std::string text, std::vector<int> args) {
        Node n;
        n.kind = kind;
        n.text = std::move(text);
        n.args = std::move(args);
        return add(std::move(n));
    }
    const Node& at(int i) const { return expr_->nodes[static_cast<std::size_t>(i)]; }

    bool isCondition(int i) const {
        const Node& n = at(i);
        switch (n.kind) {
        case Kind::Compare:
        case Kind::Logic:
        case Kind::Not:
            return true;
        case Kind::Group:
            return isCondition(n.args[0]);
        default:
            return false;
        }
    }
    void requireNumber(int i, std::size_t column) const {
        if (isCondition(i)) fail(column, "a condition where a number is needed");
    }
    void requireCondition(int i, std::size_t column) const {
        if (!isCondition(i)) fail(column, "a number where a condition is needed");
    }
    void deeper(int depth) const {
        if (depth > kMaxDepth) fail(token_.column, "nested too deeply");
    }

    int parseOr(int depth) {
        deeper(depth);
        std::size_t column = token_.column;
        int left = parseAnd(depth + 1);
        while (isWord("or")) {
            requireCondition(left, column);
            next();
            column = token_.column;
            const int right = parseAnd(depth + 1);
            requireCondition(right, column);
            left = node(Kind::Logic, "or", {left, right});
        }
        return left;
    }
    int parseAnd(int depth) {
        deeper(depth);
        std::size_t column = token_.column;
        int left = parseNot(depth + 1);
        while (isWord("and")) {
            requireCondition(left, column);
            next();
            column = token_.column;
            const int right = parseNot(depth + 1);
            requireCondition(right, column);
            left = node(Kind::Logic, "and", {left, right});
        }
        return left;
    }
    int parseNot(int depth) {
        deeper(depth);
        if (isWord("not")) {
            next();
            const std::size_t column = token_.column;
            const int a = parseNot(depth + 1);
            requireCondition(a, column);
            return node(Kind::Not, "not", {a});
        }
        return parseCompare(depth + 1);
    }
    int parseCompare(int depth) {
        deeper(depth);
        const std::size_t column = token_.column;
        const int left = parseSum(depth + 1);
        for (const char* op : {"==", "!=", "<=", ">=", "<", ">"}) {
            if (!isOp(op)) continue;
            requireNumber(left, column);
            next();
            const std::size_t rightColumn = token_.column;
            const int right = parseSum(depth + 1);
            requireNumber(right, rightColumn);
            return node(Kind::Compare, op, {left, right});
        }
        return left;
    }
    int parseSum(int depth) {
        deeper(depth);
        std::size_t column = token_.column;
        int left = parseTerm(depth + 1);
        while (isOp("+") || isOp("-")) {
            requireNumber(left, column);
            const std::string op = token_.text;
            next();
            column = token_.column;
            const int right = parseTerm(depth + 1);
            requireNumber(right, column);
            left = node(Kind::Binary, op, {left, right});
        }
        return left;
    }
    int parseTerm(int depth) {
        deeper(depth);
        std::size_t column = token_.column;
        int left = parseUnary(depth + 1);
        while (isOp("*") || isOp("/")) {
            requireNumber(left, column);
            const std::string op = token_.text;
            next();
            column = token_.column;
            const int right = parseUnary(depth + 1);
            requireNumber(right, column);
            left = node(Kind::Binary, op, {left, right});
        }
        return left;
    }
    int parseUnary(int depth) {
        deeper(depth);
        if (isOp("-")) {
            next();
            const std::size_t column = token_.column;
            const int a = parseUnary(depth + 1);
            requireNumber(a, column);
            return node(Kind::Negate, "-", {a});
        }
        return parsePower(depth + 1);
    }
    int parsePower(int depth) {
        deeper(depth);
        const std::size_t column = token_.column;
        const int base = parsePrimary(depth + 1);
        if (!isOp("^")) return base;
        requireNumber(base, column);
        next();
        const std::size_t expColumn = token_.column;
        const int exponent = parseUnary(depth + 1);
        requireNumber(exponent, expColumn);
        return node(Kind::Binary, "^", {base, exponent});
    }

    int parsePrimary(int depth) {
        deeper(depth);
        const Token t = token_;
        if (t.type == Token::Type::Number) {
            next();
            Node n;
            n.kind = Kind::Number;
            n.text = t.text;
            char* end = nullptr;
            n.number = std::strtod(t.text.c_str(), &end);
            if (end != t.text.c_str() + t.text.size() || !std::isfinite(n.number))
                fail(t.column, "not a number: \"" + printable(t.text) + "\"");
            return add(std::move(n));
        }
        if (isOp("(")) {
            next();
            const int inner = parseOr(depth + 1);
            expectOp(")");
            return node(Kind::Group, "()", {inner});
        }
        if (t.type == Token::Type::Quoted) {
            next();
            return blockQuantity(t.text, t.column);
        }
        if (t.type != Token::Type::Ident)
            fail(t.column, "expected a number or a name, found " + describe(t));
        next();
        if (t.text == "hit" && isOp(".")) {
            next();
            if (token_.type != Token::Type::Ident ||
                std::find(lessonHitQuantities().begin(), lessonHitQuantities().end(),
                          token_.text) == lessonHitQuantities().end())
                fail(token_.column, "expected one of the collision's numbers after \"hit.\" (m1, "
                                    "m2, v1, v2, v1after, v2after, u, C, t, toi, x1, y1, x2, y2, "
                                    "axis)");
            const std::string name = token_.text;
            next();
            return node(Kind::Hit, name, {});
        }
        if (t.text == "abs" || t.text == "sqrt" || t.text == "min" || t.text == "max" ||
            t.text == "floor" || t.text == "ceil" || t.text == "atan") {
            expectOp("(");
            std::vector<int> args;
            const std::size_t count = t.text == "min" || t.text == "max" ? 2 : 1;
            for (std::size_t i = 0; i < count; ++i) {
                if (i > 0) expectOp(",");
                const std::size_t column = token_.column;
                const int a = parseSum(depth + 1);
                requireNumber(a, column);
                args.push_back(a);
            }
            expectOp(")");
            return node(Kind::Call, t.text, args);
        }
        if (isOp(".")) return blockQuantity(t.text, t.column);
        if (std::find(lessonGlobalNames().begin(), lessonGlobalNames().end(), t.text) !=
            lessonGlobalNames().end())
            return node(Kind::Global, t.text, {});
        for (std::size_t v = 0; v < values_.size(); ++v) {
            if (values_[v] != t.text) continue;
            Node n;
            n.kind = Kind::Value;
            n.text = t.text;
            n.block = static_cast<int>(v);
            return add(std::move(n));
        }
        fail(t.column, "unknown name \"" + printable(t.text) +
                           "\" (a block's quantity is NAME.QUANTITY, e.g. m1.vx; the world's: C, "
                           "g, mu, rate, dt, t, collisions, ke, px, ...)");
    }

    // NAME.QUANTITY, the name read; the token is the '.'.
    int blockQuantity(const std::string& name, std::size_t column) {
        expectOp(".");
        if (token_.type != Token::Type::Ident)
            fail(token_.column, "expected a quantity after \"" + printable(name) + ".\"");
        const std::string written = token_.text;
        std::string quantity = written;
        const std::size_t quantityColumn = token_.column;
        next();
        int block = -1;
        for (std::size_t b = 0; b < scene_.blocks.size(); ++b)
            if (scene_.blocks[b].name == name) block = static_cast<int>(b);
        if (block < 0)
            fail(column, "no block named \"" + printable(name) + "\" in the step's scene");
        bool atSetup = false;
        if (quantity.size() > 1 && quantity.back() == '0') {
            quantity.pop_back();
            atSetup = true;
        }
        if (std::find(lessonBlockQuantities().begin(), lessonBlockQuantities().end(), quantity) ==
            lessonBlockQuantities().end())
            fail(quantityColumn, "unknown quantity \"" + printable(written) +
                                     "\" (x, y, vx, vy, m, w, h, left, right, top, bottom, "
                                     "speed, px, py, ke, fx, fy; add 0 for the setup: vx0)");
        Node n;
        n.kind = Kind::Block;
        n.text = quantity;
        n.block = block;
        n.atSetup = atSetup;
        return add(std::move(n));
    }
};

} // namespace

LessonExpr parseLessonExpr(const std::string& text, const Scene& scene,
                           const std::vector<std::string>& valueNames, bool condition,
                           const std::string& path, std::size_t columnOffset) {
    if (text.empty()) throw ValueError{path, "must not be empty"};
    Parser parser(text, scene, valueNames, path, columnOffset);
    return parser.parse(condition);
}
