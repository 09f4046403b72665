#include "view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

double panelWidth(float uiScale, double displayWidth) {
    return std::min(kPanelPxAtScale1 * static_cast<double>(uiScale), displayWidth * kMaxPanelShare);
}

bool panelFits(float uiScale, double displayWidth) {
    return kPanelPxAtScale1 * static_cast<double>(uiScale) <= displayWidth * kMaxPanelShare;
}

double sceneLabelPx(float uiScale, float labelScale, double displayHeight) {
    const double share = displayHeight > 0.0 ? std::ceil(kSceneLabelShare * displayHeight) : 0.0;
    return std::max(share, std::round(kBaseFontPx * static_cast<double>(uiScale * labelScale)));
}

double fitMarginPx(float uiScale, float labelScale, double displayHeight) {
    return std::max(kFitMarginPx * static_cast<double>(uiScale),
                    sceneLabelPx(uiScale, labelScale, displayHeight) + kAxisRowGapPx);
}

std::string ClassroomScreen::name() const {
    char text[64];
    std::snprintf(text, sizeof text, "%dx%d_ui%g", width, height, static_cast<double>(uiScale));
    return text;
}

std::vector<ClassroomScreen> classroomScreens() {
    constexpr int kSizes[][2] = {{1024, 768},  {1280, 720},  {1280, 800}, {1366, 768},
                                 {1920, 1080}, {1920, 1200}, {3840, 2160}};
    constexpr float kScales[] = {1.0f, 1.25f, 1.5f, 2.0f};
    std::vector<ClassroomScreen> out;
    for (const auto& size : kSizes)
        for (const float scale : kScales)
            if (panelFits(scale, size[0])) out.push_back({size[0], size[1], scale});
    return out;
}

Layout computeAppLayout(const View& view, bool captionBar, double displayWidth,
                        double displayHeight) {
    LayoutInput in;
    in.displayWidth = displayWidth;
    in.displayHeight = displayHeight;
    in.uiScale = view.uiScale;
    // A lesson's caption bar over the top of the scene (and the column), presenting too.
    if (captionBar) in.topInset = std::min(view.captionHeight, displayHeight * 0.5);
    if (view.presentMode) return computeLayout(in); // the scene alone (under a lesson's caption)
    if (!view.uiVisible) {
    } else if (sheetLayout(displayWidth, view.uiScale, displayHeight, view.touch)) {
        in.panelHeight = view.sheetOpen ? displayHeight * kSheetOpenShare
                                        : kSheetBarPx * static_cast<double>(view.uiScale);
    } else {
        in.panelWidth = panelWidth(view.uiScale, displayWidth);
    }
    for (const OverlayInfo& row : kOverlays) {
        // Shown, or (in a lesson) opened at the step's moment: its room kept from the setup on,
        // unless it docks under the panel (it takes that room from the panel, not the scene).
        const bool underPanel = row.place.side == DockSide::Panel && in.panelWidth > 0.0;
        const bool kept =
            view.show.*row.flag || (captionBar && !underPanel && view.reserved.*row.flag);
        if (!row.title || !kept || isFloating(view, row.title)) continue;
        const auto& front = view.frontWindows;
        const auto at = std::find(front.begin(), front.end(), row.title);
        // A window the lesson only reserves is never the one a folded region shows (it is not
        // drawn): it ranks below every window that is on.
        const int rank = !(view.show.*row.flag)
                             ? -1
                             : (at == front.end() ? 0 : static_cast<int>(at - front.begin()) + 1);
        in.windows.push_back({row.title, row.place.side, row.place.minExtent, row.place.weight,
                              row.place.crossExtent, row.place.heightShare, rank});
    }
    return computeLayout(in);
}

ScreenRect sceneViewport(const View& view, bool captionBar, double displayWidth,
                         double displayHeight) {
    return computeAppLayout(view, captionBar, displayWidth, displayHeight).scene;
}

void updateCamera(View& view, const World& world, bool captionBar, double displayWidth,
                  double displayHeight) {
    // Windows turned on since the last layout come to the front (the first of the table's rows
    // turned on together in front of the others).
    for (std::size_t i = kOverlayCount; i-- > 0;) {
        const OverlayInfo& row = kOverlays[i];
        if (row.title && view.show.*row.flag && !(view.shownBefore.*row.flag))
            bringToFront(view, row.title);
    }
    view.shownBefore = view.show;
    view.layout = computeAppLayout(view, captionBar, displayWidth, displayHeight);
    view.camera.setViewport(view.layout.scene);
    if (view.autoFit) {
        const Bounds& bounds = view.fitBounds ? *view.fitBounds : world.bounds;
        view.camera.fit(bounds, fitMarginPx(view.uiScale, view.labelScale, displayHeight));
    }
    view.camera.setCentre(view.camera.centre() +
                          followShift(view.frameCamera, world, view.frame, view.autoFit));
}

void showNewScene(View& view, const Scene& scene) {
    if (!view.overlaysChosen) view.show.vectors = vectorsByDefault(scene);
    view.autoFit = true;
}

void followNewRun(View& view, const World& world) {
    anchorFrameCamera(view.frameCamera, world);
}

void setViewFrame(View& view, ViewFrame frame) {
    view.frame = frame;
    view.frameCamera.anchored = false;
}

void setPresentMode(View& view, bool on) {
    view.presentMode = on;
    view.autoFit = true; // the scene's rectangle changes: fit the world into it again
}

void setUiScale(View& view, float scale) {
    if (!(scale == scale)) return;
    view.uiScale = std::clamp(scale, kMinUiScale, kMaxUiScale);
}

void applyShowSet(View& view, const ShowSet& show) {
    view.overlaysChosen = true;
    view.uiVisible = !show.none;
    view.show = show.overlays;
}

void bringToFront(View& view, const std::string& title) {
    auto& f = view.frontWindows;
    f.erase(std::remove(f.begin(), f.end(), title), f.end());
    f.push_back(title);
}

bool isFloating(const View& view, const std::string& title) {
    return std::find(view.floatingWindows.begin(), view.floatingWindows.end(), title) !=
           view.floatingWindows.end();
}

void setFloating(View& view, const std::string& title, bool floating) {
    auto& f = view.floatingWindows;
    f.erase(std::remove(f.begin(), f.end(), title), f.end());
    if (floating) f.push_back(title);
}
