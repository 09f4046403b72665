// The app's side of the overlay table (app/lesson/vocabulary.h, SANDBOX_OVERLAYS): the flags of
// the shown overlays (Overlays) and each row's names, title and place (kOverlays); the draw
// functions are the ImGui layer's (app/gui/ui/widgets/overlay_window.h).
#pragma once

#include "dock_layout.h"
#include "vocabulary.h"

#include <cstddef>
#include <string>
#include <vector>

// Which overlays are shown: one flag per row.
struct Overlays {
#define SANDBOX_OVERLAY_FLAG(member, name, label, tooltip, on, title, place, draw) bool member = on;
    SANDBOX_OVERLAYS(SANDBOX_OVERLAY_FLAG)
#undef SANDBOX_OVERLAY_FLAG
};

// A row of the table, without its draw function (the ImGui layer holds those: ui/widgets/overlay_window.h).
struct OverlayInfo {
    bool Overlays::*flag;
    const char* name;
    const char* label;
    const char* tooltip;
    const char* title; // nullptr: drawn over the scene, no window
    DockWish place;
};

// The rows' indices: OverlayId::plots, ...
enum class OverlayId : std::size_t {
#define SANDBOX_OVERLAY_ID(member, name, label, tooltip, on, title, place, draw) member,
    SANDBOX_OVERLAYS(SANDBOX_OVERLAY_ID)
#undef SANDBOX_OVERLAY_ID
};

inline constexpr OverlayInfo kOverlays[] = {
#define SANDBOX_OVERLAY_INFO(member, name, label, tooltip, on, title, place, draw)                 \
    {&Overlays::member, name, label, tooltip, title, place},
    SANDBOX_OVERLAYS(SANDBOX_OVERLAY_INFO)
#undef SANDBOX_OVERLAY_INFO
};
inline constexpr std::size_t kOverlayCount = sizeof kOverlays / sizeof kOverlays[0];

inline const OverlayInfo& overlayInfo(OverlayId id) {
    return kOverlays[static_cast<std::size_t>(id)];
}

// A --show LIST: which overlays (names from the table), and "none" (no panels and no overlays).
struct ShowSet {
    bool none = false;
    Overlays overlays = noOverlays();
    static Overlays noOverlays() {
        Overlays o;
        for (const OverlayInfo& i : kOverlays) o.*i.flag = false;
        return o;
    }
};

// Turns the overlay called `name` on or off; false for an unknown name.
bool setOverlay(Overlays& overlays, const std::string& name, bool on);
// "none, trails, vectors, ...": the names --show accepts.
std::string showNames();
// Parses a comma-separated --show list; false with a message for an unknown name.
bool parseShowList(const std::string& text, ShowSet& out, std::string* error);
