#include "lesson_text.h"

#include "scene_json.h"
#include "text_format.h"

using scene_json::ValueError;

namespace {

constexpr const char* kAsWritten = "as written:";
// Dropped around an {as written: ...} text once it is put in parentheses.
constexpr const char* kAsWrittenSeparators = " ,;:";

// The 1-based column, in characters, of byte `at` of `text`.
std::size_t columnOf(const std::string& text, std::size_t at) {
    std::size_t column = 1;
    for (std::size_t i = 0; i < at && i < text.size(); ++i)
        if ((static_cast<unsigned char>(text[i]) & 0xc0) != 0x80) ++column;
    return column;
}

} // namespace

bool LessonText::computed() const {
    for (const Part& p : parts)
        if (p.kind != Part::Kind::Literal) return true;
    return false;
}

LessonText parseLessonText(const std::string& text, const Scene& scene,
                           const std::vector<std::string>& valueNames, const std::string& path) {
    LessonText out;
    out.source = text;
    std::string literal;
    const auto flush = [&] {
        if (literal.empty()) return;
        LessonText::Part p;
        p.text = literal;
        out.parts.push_back(std::move(p));
        literal.clear();
    };
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        if ((c == '{' || c == '}') && i + 1 < text.size() && text[i + 1] == c) {
            literal += c;
            i += 2;
            continue;
        }
        if (c == '}')
            throw ValueError{path, "column " + std::to_string(columnOf(text, i)) +
                                       ": a \"}\" closes nothing (write }} for a brace)"};
        if (c != '{') {
            literal += c;
            ++i;
            continue;
        }
        const std::size_t close = text.find('}', i + 1);
        const std::size_t nested = text.find('{', i + 1);
        if (close == std::string::npos || nested < close)
            throw ValueError{path, "column " + std::to_string(columnOf(text, i)) +
                                       ": a \"{\" that is not closed (write {{ for a brace)"};
        flush();
        std::string inner = text.substr(i + 1, close - i - 1);
        std::size_t innerStart = i + 1;
        LessonText::Part p;
        if (inner.rfind(kAsWritten, 0) == 0) {
            p.kind = LessonText::Part::Kind::AsWritten;
            p.text = inner.substr(std::string(kAsWritten).size()); // its spaces are the text's
            // Nothing but spaces and separators says nothing either (",": they are dropped).
            if (p.text.find_first_not_of(kAsWrittenSeparators) == std::string::npos)
                throw ValueError{path, "column " + std::to_string(columnOf(text, i)) +
                                           ": {as written: ...} says nothing"};
        } else {
            p.kind = LessonText::Part::Kind::Value;
            if (!inner.empty() && inner[0] == '=') {
                p.kind = LessonText::Part::Kind::Equation;
                inner.erase(0, 1);
                ++innerStart;
            }
            const std::size_t lead = inner.find_first_not_of(' ');
            if (lead == std::string::npos)
                throw ValueError{path,
                                 "column " + std::to_string(columnOf(text, i)) + ": an empty {}"};
            inner = inner.substr(lead, inner.find_last_not_of(' ') - lead + 1);
            innerStart += lead;
            p.expr = parseLessonExpr(inner, scene, valueNames, false, path,
                                     columnOf(text, innerStart) - 1);
        }
        out.parts.push_back(std::move(p));
        i = close + 1;
    }
    flush();
    return out;
}

std::string renderLessonText(const LessonText& text, const ExprScope& scope, bool asWritten) {
    std::string out;
    for (const LessonText::Part& p : text.parts) {
        switch (p.kind) {
        case LessonText::Part::Kind::Literal:
            out += p.text;
            break;
        case LessonText::Part::Kind::Value:
            out += formatNumber(evaluate(p.expr, scope));
            break;
        case LessonText::Part::Kind::Equation:
            out += printedEquation(p.expr, scope);
            break;
        case LessonText::Part::Kind::AsWritten: {
            if (asWritten) {
                out += p.text;
                break;
            }
            // ", all kinetic energy is kept" -> " (as written: all kinetic energy is kept)";
            // "Both keep the momentum:" -> " (as written: Both keep the momentum)" (a colon
            // before the parenthesis's end read as a typo on screen).
            const std::size_t from = p.text.find_first_not_of(kAsWrittenSeparators);
            const std::size_t to = p.text.find_last_not_of(kAsWrittenSeparators);
            out += " (as written: " + p.text.substr(from, to - from + 1) + ")";
            break;
        }
        }
    }
    return out;
}
