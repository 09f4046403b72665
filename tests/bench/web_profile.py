#!/usr/bin/python3
"""Where the browser build's frame time goes: Chromium's own CPU profiler (the DevTools
protocol's Profiler domain) over the running page, its samples summed by function.

  tests/bench/web_profile.py SITE [QUERY] [--frames N] [--ratio R] [--top K] [--gl-calls]
                             [--inclusive] [--first-frame] [--invokes]

SITE is a build-web/ folder; QUERY the page's URL parameters (e.g. "scene=gas_500&show=plots").
Build the site with wasm function names kept to read them (a profiling build: the link's
--profiling-funcs, which changes no code):

  SANDBOX_WEB_OUT=$PWD/build-web-prof scripts/web.sh build -DCMAKE_EXE_LINKER_FLAGS=--profiling-funcs

At 1280x720 (ratio R, default 1), the simulation running, after 30 frames to warm up, the page is
profiled over N frames (default 300) and the functions with the most self time are printed, as
a share of the time inside the page's requestAnimationFrame callbacks (the frames' JavaScript,
timed as web_frame_bench.py times it) and in ms per frame. A profile, not a benchmark: the shares
hold under load, the ms do not. With --gl-calls, the WebGL calls per frame are counted by name
instead (each crosses from wasm to JavaScript and into the browser's WebGL). With --inclusive,
the functions are also listed by their total time (their own and their callees': where a frame's
parts go, e.g. ImGui::NewFrame, appFrame, appRender, tellPage). With --first-frame, the page
loaded once, then its warm reload is profiled up to its first frame shown (web_frame_bench.py's
first frame): where that time goes (compiling the wasm, main(), the fonts, the first frame), in ms.
With --invokes, the calls per frame through emscripten's invoke_ wrappers are counted by the
function called (named in a profiling build): with exceptions in emscripten's JavaScript mode
(-fexceptions), a call that may throw from code with something to clean up leaves the wasm for
JavaScript and comes back through the function table; with WebAssembly's own exceptions
(-fwasm-exceptions, cmake/web.cmake) there are none.
"""
import collections
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import web_frame_bench  # noqa: E402  (its TIMER, serve, and browser_test's Page)

browser_test = web_frame_bench.browser_test

# Counts the page's WebGL calls by name (installed before the page's scripts run).
GL_COUNTER = """
(() => {
  window.sandboxGlCalls = {};
  const proto = WebGL2RenderingContext.prototype;
  for (const name of Object.getOwnPropertyNames(proto)) {
    const d = Object.getOwnPropertyDescriptor(proto, name);
    if (typeof d.value !== 'function' || name === 'constructor') continue;
    const f = d.value;
    proto[name] = function () {
      window.sandboxGlCalls[name] = (window.sandboxGlCalls[name] || 0) + 1;
      return f.apply(this, arguments);
    };
  }
})();
"""


# Counts the calls through emscripten's invoke_ wrappers by the function table's index: the
# wrappers are the wasm's imports that are JavaScript functions named invoke_* (the imports' and
# their modules' own names are shortened), wrapped as the page instantiates the wasm.
INVOKE_COUNTER = """
(() => {
  window.sandboxInvokes = {};
  const wrap = (imports) => {
    for (const module of Object.values(imports || {})) {
      for (const name of Object.keys(module)) {
        const f = module[name];
        if (typeof f !== 'function' || !f.name.startsWith('invoke_')) continue;
        module[name] = function (index) {
          window.sandboxInvokes[index] = (window.sandboxInvokes[index] || 0) + 1;
          return f.apply(this, arguments);
        };
      }
    }
  };
  for (const name of ['instantiate', 'instantiateStreaming']) {
    const original = WebAssembly[name];
    WebAssembly[name] = function (source, imports) {
      wrap(imports);
      return original.apply(this, arguments);
    };
  }
})();
"""


def wasm_function_names(path):
    """The wasm's function names by function index, from its name section (a profiling build's;
    {} without one)."""
    data = open(path, "rb").read()

    def leb(at):
        value = shift = 0
        while True:
            byte = data[at]
            at += 1
            value |= (byte & 0x7F) << shift
            shift += 7
            if byte < 0x80:
                return value, at

    names, at = {}, 8
    while at < len(data):
        section, size, at = data[at], *leb(at + 1)
        end = at + size
        length, inner = leb(at)
        if section == 0 and data[inner:inner + length] == b"name":
            inner += length
            while inner < end:
                kind, size, inner = data[inner], *leb(inner + 1)
                if kind == 1:  # function names
                    count, j = leb(inner)
                    for _ in range(count):
                        index, j = leb(j)
                        length, j = leb(j)
                        names[index] = data[j:j + length].decode("utf-8", "replace")
                        j += length
                inner += size
        at = end
    return names


def without_template_arguments(name):
    """`name` with every template's arguments left out (std::vector<int> -> std::vector<>)."""
    out, depth = [], 0
    for at, c in enumerate(name):
        if c == ">" and depth:
            depth -= 1
        if depth == 0:
            out.append(c)
        if c == "<" and not name[:at + 1].endswith("operator<"):
            depth += 1
    return "".join(out)


def count_invokes(page, site, frames, top):
    """Prints the invoke_ calls per frame over `frames` frames, by the function called."""
    count = web_frame_bench.FRAME_COUNT
    before = page.evaluate("Object.assign({}, window.sandboxInvokes)")
    start = page.evaluate(count)
    page.wait(lambda: page.evaluate(count) >= start + frames, "the frames")
    after = page.evaluate("Object.assign({}, window.sandboxInvokes)")
    frames = page.evaluate(count) - start
    slots = sorted(after, key=lambda k: before.get(k, 0) - after[k])
    # A table slot's function is the wasm's function of that index (its name is the index).
    indices = page.evaluate("[" + ",".join(slots) + "].map((i) => wasmTable.get(i).name)")
    names = wasm_function_names(os.path.join(site, "sandbox.wasm"))
    calls = [((after[k] - before.get(k, 0)) / frames,
              without_template_arguments(names.get(int(f), f"wasm-function[{f}]")))
             for k, f in zip(slots, indices)]
    print(f"{sum(n for n, _ in calls):.1f} calls per frame through invoke_ wrappers, over "
          f"{frames} frames; the top {top} by the function called:")
    for n, name in calls[:top]:
        if n >= 0.05:
            print(f"  {n:8.1f}  {name[:110]}")


def self_times(profile):
    """ms of self time per (function, place), from the profile's nodes and sample deltas."""
    nodes = {n["id"]: n for n in profile["nodes"]}
    ms = collections.Counter()
    for node_id, delta in zip(profile["samples"], profile["timeDeltas"]):
        frame = nodes[node_id]["callFrame"]
        name = frame["functionName"] or "(anonymous)"
        place = os.path.basename(frame["url"]) if frame["url"] else ""
        ms[(name, place)] += delta / 1000.0
    return ms


def total_times(profile):
    """ms of total time per function name: each sample counts once for every function on its
    stack (a recursive one once)."""
    nodes = {n["id"]: n for n in profile["nodes"]}
    parent = {}
    for n in profile["nodes"]:
        for child in n.get("children", ()):
            parent[child] = n["id"]
    ms = collections.Counter()
    for node_id, delta in zip(profile["samples"], profile["timeDeltas"]):
        names, at = set(), node_id
        while at is not None:
            names.add(nodes[at]["callFrame"]["functionName"] or "(anonymous)")
            at = parent.get(at)
        for name in names:
            ms[name] += delta / 1000.0
    return ms


def print_top(ms, busy, per, unit, top, idle):
    for (name, place), v in [(k, v) for k, v in ms.most_common() if k[0] not in idle][:top]:
        print(f"  {100 * v / busy:5.1f}%  {v / per:7.3f} {unit}  {name[:100]}  {place}")


def profile_first_frame(page, base, site, query, top):
    """The warm reload profiled up to its first frame: self and total times in ms."""
    page.open(base + ("?" + query if query else ""))  # the cold load fills the cache
    page.call("Profiler.enable")
    page.call("Profiler.setSamplingInterval", interval=100)  # us
    page.call("Profiler.start")
    page.reload()
    profile = page.call("Profiler.stop")["profile"]
    first = page.evaluate("window.sandboxFirstFrame")
    idle = {"(idle)", "(program)", "(garbage collector)", "(root)"}
    ms = self_times(profile)
    busy = sum(v for (name, _), v in ms.items() if name not in idle)
    print(f"{site} ?{query}: first frame at {first:.0f} ms after the reload's start; profiled "
          f"{sum(ms.values()):.0f} ms, {busy:.0f} ms in functions")
    for name in sorted(idle - {"(root)"}):
        print(f"  {name}: {sum(v for (n, _), v in ms.items() if n == name):.0f} ms")
    print(f"top {top} functions by self time:")
    print_top(ms, busy, 1, "ms", top, idle)
    print(f"top {top} functions by total time (their callees' too):")
    totals = collections.Counter({(k, ""): v for k, v in total_times(profile).items()})
    print_top(totals, busy, 1, "ms", top, idle)
    return 0


def main():
    args = sys.argv[1:]
    options = {"--frames": 300, "--ratio": 1.0, "--top": 15}
    count_gl = "--gl-calls" in args  # count the WebGL calls per frame instead of profiling
    if count_gl:
        args.remove("--gl-calls")
    inclusive = "--inclusive" in args  # also the functions by total time
    if inclusive:
        args.remove("--inclusive")
    first_frame = "--first-frame" in args  # the warm reload up to its first frame
    if first_frame:
        args.remove("--first-frame")
    invokes = "--invokes" in args  # the calls through invoke_ wrappers instead of profiling
    if invokes:
        args.remove("--invokes")
    for key in list(options):
        if key in args:
            at = args.index(key)
            options[key] = type(options[key])(args[at + 1])
            del args[at:at + 2]
    if not args:
        print(__doc__)
        return 2
    site, query = args[0], (args[1] if len(args) > 1 else "")
    server, base = web_frame_bench.serve(site)
    page = browser_test.Page(1280, 720, options["--ratio"])
    try:
        if first_frame:
            return profile_first_frame(page, base, site, query, options["--top"])
        count = web_frame_bench.FRAME_COUNT
        scripts = (GL_COUNTER,) if count_gl else (INVOKE_COUNTER,) if invokes else ()
        web_frame_bench.open_running(page, base, query, 30, scripts)
        if invokes:
            print(f"{site} ?{query}: ", end="")
            return count_invokes(page, site, options["--frames"], options["--top"]) or 0
        if count_gl:
            before = page.evaluate("Object.assign({}, window.sandboxGlCalls)")
            start = page.evaluate(count)
            page.wait(lambda: page.evaluate(count) >= start + options["--frames"], "the frames")
            after = page.evaluate("Object.assign({}, window.sandboxGlCalls)")
            frames = page.evaluate(count) - start
            calls = {k: (v - before.get(k, 0)) / frames for k, v in after.items()}
            print(f"{site} ?{query}: {sum(calls.values()):.1f} WebGL calls per frame:")
            for name, n in sorted(calls.items(), key=lambda kv: -kv[1]):
                if n >= 0.05:
                    print(f"  {n:7.1f}  {name}")
            return 0
        page.call("Profiler.enable")
        page.call("Profiler.setSamplingInterval", interval=100)  # us
        start = page.evaluate(count)
        page.call("Profiler.start")
        page.wait(lambda: page.evaluate(count) >= start + options["--frames"], "the frames")
        profile = page.call("Profiler.stop")["profile"]
        end = page.evaluate(count)
        frames = page.evaluate(f"window.sandboxFrameMs.slice({start}, {end})")
    finally:
        page.close()
        server.shutdown()
    ms = self_times(profile)
    in_frames = sum(frames)
    idle = {"(idle)", "(program)", "(garbage collector)"}
    busy = sum(v for (name, _), v in ms.items() if name not in idle)
    print(f"{site} ?{query} ratio {options['--ratio']}: {len(frames)} frames, "
          f"{in_frames / len(frames):.2f} ms of JavaScript per frame (mean; median "
          f"{sorted(frames)[len(frames) // 2]:.2f}); samples: {busy / len(frames):.2f} ms per "
          "frame in functions, the rest idle, (program) or GC")
    for name in sorted(idle):
        total = sum(v for (n, _), v in ms.items() if n == name)
        print(f"  {name}: {total / len(frames):.2f} ms per frame")
    print(f"top {options['--top']} functions by self time (share of the time in functions):")
    top = [(k, v) for k, v in ms.most_common() if k[0] not in idle][:options["--top"]]
    for (name, place), v in top:
        print(f"  {100 * v / busy:5.1f}%  {v / len(frames):6.3f} ms/frame  {name}  {place}")
    if inclusive:
        totals = [(k, v) for k, v in total_times(profile).most_common()
                  if k not in idle and k != "(root)"][:options["--top"]]
        print(f"top {options['--top']} functions by total time (their callees' too):")
        for name, v in totals:
            print(f"  {100 * v / busy:5.1f}%  {v / len(frames):6.3f} ms/frame  {name[:110]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
