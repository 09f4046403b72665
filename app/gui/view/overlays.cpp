#include "overlays.h"

#include <sstream>

std::string showNames() {
    std::string names = "none";
    for (const OverlayInfo& o : kOverlays) names += std::string(", ") + o.name;
    return names;
}

bool setOverlay(Overlays& overlays, const std::string& name, bool on) {
    for (const OverlayInfo& o : kOverlays) {
        if (name != o.name) continue;
        overlays.*o.flag = on;
        return true;
    }
    return false;
}

bool parseShowList(const std::string& text, ShowSet& out, std::string* error) {
    ShowSet show;
    std::istringstream in(text);
    std::string name;
    bool any = false;
    while (std::getline(in, name, ',')) {
        if (name.empty()) continue;
        any = true;
        if (name == "none") {
            show.none = true;
            continue;
        }
        if (!setOverlay(show.overlays, name, true)) {
            if (error) {
                *error = "unknown --show name '" + name + "' (expected " + showNames() + ")";
            }
            return false;
        }
    }
    if (!any) {
        if (error) *error = "--show needs at least one name";
        return false;
    }
    out = show;
    return true;
}
