// A link for what is on screen (the browser build's address bar and its "Copy link"):
//   ?scene=newtons_cradle&method=turn-based&show=plots,inspector&frame=com
//   ?lesson=lecture3&step=5
//   ?lesson=lecture3&step=13#scene=<the step's setup as the student changed it>
//   ?show=plots#scene=<the scene itself, compressed>
// The query names a shipped scene or lesson and what differs from opening it plainly (the
// parameters of url_params.h). When the scene on screen is not a shipped one as it starts (its
// blocks or settings were edited, it came from a file, or it has run on), the link carries the
// scene itself in its fragment: the page compresses sceneToJson(app.sim.currentScene())
// (deflate-raw, base64url) into #scene=..., and opening the link restores exactly those blocks and
// settings (at t = 0). Inside a lesson the query names the lesson and the step, and when the
// student changed the step's setup (lesson_session's lessonChanges: C, a mass, a block moved...)
// the fragment carries that setup: the link opens the step, paused at its setup, in the student's
// world. Pure logic: the web main asks it every frame and tells the page what changed.
#pragma once

#include "scene.h"

#include <cstddef>
#include <string>

struct App;

// The query for the app's state, without the '?' ("" for the default scene as it opens).
std::string linkQuery(const App& app);
// True when the link must carry the scene itself (see above).
bool linkCarriesScene(const App& app);
// The scene it carries: the one on screen, or in a lesson the step's setup (at t = 0).
Scene linkedScene(const App& app);
// The fragment's key for the carried scene, and the longest link browsers take in their address
// bar (Chromium shows about 32,000 characters; longer links are refused by some services).
inline constexpr const char* kLinkSceneKey = "scene";
inline constexpr std::size_t kMaxLinkChars = 32000;
// The message when a link with the scene would be longer than kMaxLinkChars.
std::string linkTooLongMessage(std::size_t chars);
// A scene of more blocks than this is not put in a link at all: it would never fit in
// kMaxLinkChars (gas_500 in motion takes 24,000 characters), and writing and compressing its JSON
// every half second would take the page's frames (200,000 blocks: 16 MB each time). The link
// then names the rest, and "Copy link" says why (linkTooManyBlocksMessage).
inline constexpr std::size_t kMaxLinkBlocks = 2000;
// True when the link must carry the scene and it has more than kMaxLinkBlocks blocks.
bool linkSceneTooLarge(const App& app);
std::string linkTooManyBlocksMessage(std::size_t blocks);
