#!/usr/bin/python3
"""What the browser build weighs, measured (the README's table is this script's output, never
typed): each file a browser downloads, raw and gzip -9 compressed (as web servers send it), and
the one-file build.

  scripts/web_sizes.py SITE                  print the table (SITE: build-web/)
  scripts/web_sizes.py SITE --readme README  write it into README between its markers
  scripts/web_sizes.py SITE --check README   exit 1 when a figure in README is more than 10% (and
                                             4 KB) off (a ctest: the README stays true as the
                                             code grows)
"""
import gzip
import os
import re
import sys

FILES = ["index.html", "sw.js", "sandbox.js", "sandbox.wasm", "sandbox.data"]
ONE_FILE = "sandbox-offline.html"
BEGIN = "<!-- web sizes: scripts/web_sizes.py build-web --readme README.md -->"
END = "<!-- end of web sizes -->"
TOLERANCE = 0.10  # and at least SLACK bytes: small files may change without a new table
SLACK = 4096


def measure(site):
    rows = []
    for name in FILES + [ONE_FILE]:
        data = open(os.path.join(site, name), "rb").read()
        rows.append((name, len(data), len(gzip.compress(data, 9, mtime=0))))
    return rows


def table(rows):
    lines = ["| file | bytes | gzip -9 |", "|------|------:|--------:|"]
    served = rows[:-1]
    for name, raw, packed in served:
        lines.append(f"| `{name}` | {raw:,} | {packed:,} |")
    lines.append(f"| the page, in all | {sum(r[1] for r in served):,} | "
                 f"{sum(r[2] for r in served):,} |")
    name, raw, packed = rows[-1]
    lines.append(f"| `{name}` (the one-file build) | {raw:,} | {packed:,} |")
    return "\n".join(lines)


def block(readme_text):
    at, to = readme_text.find(BEGIN), readme_text.find(END)
    if at < 0 or to < at:
        raise SystemExit(f"web_sizes: the README has no block between '{BEGIN}' and '{END}'")
    return at, to


def main():
    if len(sys.argv) not in (2, 4):
        print(__doc__)
        return 2
    site = sys.argv[1]
    missing = [f for f in FILES + [ONE_FILE] if not os.path.exists(os.path.join(site, f))]
    if missing:
        print(f"SKIP: {site} has no {', '.join(missing)}: build it with scripts/web.sh build")
        return 77
    rows = measure(site)
    text = table(rows)
    if len(sys.argv) == 2:
        print(text)
        return 0
    mode, readme = sys.argv[2], sys.argv[3]
    content = open(readme, encoding="utf-8").read()
    at, to = block(content)
    if mode == "--readme":
        content = content[:at] + BEGIN + "\n" + text + "\n" + content[to:]
        open(readme, "w", encoding="utf-8").write(content)
        return 0
    if mode != "--check":
        print(__doc__)
        return 2
    written = content[at:to]
    wrong = []
    for name, raw, packed in rows:
        m = re.search(r"\| `" + re.escape(name) + r"`[^|]*\| ([\d,]+) \| ([\d,]+) \|", written)
        if not m:
            wrong.append(f"{name}: not in the README's table")
            continue
        for what, built, said in (("bytes", raw, m.group(1)), ("gzip -9", packed, m.group(2))):
            said = int(said.replace(",", ""))
            if abs(built - said) > max(TOLERANCE * built, SLACK):
                wrong.append(f"{name} {what}: the README says {said:,}, the build has {built:,}")
    if wrong:
        print("The README's sizes are off by more than 10% (and 4 KB): run "
              "scripts/web_sizes.py build-web --readme README.md\n  " + "\n  ".join(wrong))
        return 1
    print("the README's sizes are within 10% of the build's:\n" + text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
