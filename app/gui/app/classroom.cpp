#include "classroom.h"

#include "number_text.h"
#include "save_naming.h"
#include "text_format.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

EscapeEffect escapeEffect(bool dialogOpen, bool helpOpen, bool presentMode, bool fullscreen) {
    if (dialogOpen) return EscapeEffect::CloseDialog;
    if (helpOpen && !presentMode) return EscapeEffect::CloseHelp; // Help is hidden in present mode
    if (presentMode) return EscapeEffect::LeavePresent;
    if (fullscreen) return EscapeEffect::LeaveFullscreen;
    return EscapeEffect::Nothing;
}

std::string firstSentence(const std::string& text) {
    const std::size_t end = text.find(". ");
    return end == std::string::npos ? text : text.substr(0, end + 1);
}

std::string methodAndTime(Method method, double time) {
    std::string text = std::string(methodName(method)) + "   ·   t = ";
    number_text::appendFixed(text, time, 2); // "%.2f"
    return text + " s";
}

std::string presentCaption(const std::string& sceneName, const std::string& description,
                           Method method, double time, bool withDescription) {
    std::string what = sceneName;
    if (withDescription && !description.empty()) what += ": " + firstSentence(description);
    return what + "   ·   " + methodAndTime(method, time);
}

std::string lessonBarStatus(bool presentMode, Method method, double time, bool touch, bool hinted) {
    if (presentMode) return methodAndTime(method, time);
    if (touch) return ""; // no keys: the hint names the button to tap (lessonHint)
    return hinted ? "PageUp back, R restart" : "PageDown next, PageUp back, R restart";
}

std::string startHint(bool paused, double time, bool firstLaunch, bool touch) {
    if (!paused || time != 0.0) return "";
    // A finger has no P or F1: it names the bar's buttons instead (the browser on a phone).
    if (touch)
        return firstLaunch ? "Tap Play   ·   Step: one step   ·   Help: gestures, overlays"
                           : "Tap Play";
    if (firstLaunch) return "P to play   ·   N one step   ·   F1 help (keys, overlays)";
    return "P to play";
}

TypedValue checkTypedValue(const char* field, double typed, double current,
                           const limits::Range& range) {
    TypedValue out;
    const std::string problem = limits::violation(range, typed);
    out.ok = problem.empty();
    out.value = out.ok ? typed : current;
    if (!out.ok) out.message = std::string(field) + ": " + problem;
    return out;
}

double shownNumber(double value, const char* format) {
    // The format's first conversion: its precision and letter (flags and width change no digit).
    const char* at = std::strchr(format, '%');
    while (at && at[1] == '%') at = std::strchr(at + 2, '%');
    if (!at || !std::isfinite(value)) return value;
    const char* p = at + 1;
    while (*p && std::strchr("-+ #0", *p)) ++p;
    while (std::isdigit(static_cast<unsigned char>(*p))) ++p;
    int precision = 6; // printf's default
    if (*p == '.') {
        precision = std::atoi(p + 1);
        for (++p; std::isdigit(static_cast<unsigned char>(*p));) ++p;
    }
    const char letter = *p;
    if (!letter || !std::strchr("fFeEgG", letter)) return value;
    const char conversion[] = {'%', '.', '*', letter, '\0'};
    char text[512]; // %f of 1e300 has 301 digits
    // (number_text.h: "%.*f" and "%.*g" without printf, the same text)
    if (letter == 'f')
        number_text::printFixed(text, sizeof text, value, std::min(precision, 17));
    else if (letter == 'g')
        number_text::printGeneral(text, sizeof text, value, std::min(precision, 17));
    else
        std::snprintf(text, sizeof text, conversion, std::min(precision, 17), value);
    return std::strtod(text, nullptr);
}

bool TypedWarning::note(const char* name, const TypedValue& check) {
    if (!check.ok) {
        field = name;
        message = check.message;
    } else if (field == name) {
        clear();
    }
    return check.ok;
}

std::optional<double> restingStackTop(const Scene& scene) {
    const WorldSettings& s = scene.settings;
    if (!(s.gravity.y < 0.0) || s.gravity.x != 0.0) return std::nullopt;
    constexpr double kTouch = 1e-9;    // m: faces this close count as touching
    bool any = false, stacked = false; // stacked: a dynamic block stands on another
    double top = 0.0;
    for (const BlockDef& b : scene.blocks) {
        if (b.kind != BodyKind::Dynamic) continue;
        if (b.velocity != Vec2{}) return std::nullopt;
        const double bottom = b.position.y - b.size.y * 0.5;
        bool supported = std::abs(bottom - scene.bounds.min.y) <= kTouch;
        for (const BlockDef& o : scene.blocks) {
            if (&o == &b) continue;
            const bool below = std::abs(o.position.y + o.size.y * 0.5 - bottom) <= kTouch;
            const bool sideBySide =
                std::abs(o.position.x - b.position.x) < (o.size.x + b.size.x) * 0.5;
            if (below && sideBySide) {
                supported = true;
                stacked = stacked || o.kind == BodyKind::Dynamic;
            }
        }
        if (!supported) return std::nullopt;
        const double t = b.position.y + b.size.y * 0.5;
        top = any ? std::max(top, t) : t;
        any = true;
    }
    if (!any || !stacked) return std::nullopt;
    return top;
}
