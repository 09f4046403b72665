#!/usr/bin/python3
"""The class poll's benchmark (issue 40; reported, never a ctest test): how long a phone waits
for its vote's answer, and what holding idle phones costs the server.

Each run starts a server on 127.0.0.1, opens IDLE keep-alive connections that each ask for the
state once and then stay open (phones between two questions), then has PHONES more phones, each
on a new connection, ask for the state and vote, all at once. It reports, per run, the server's
threads and resident memory while the idle phones are held, and the vote's answer time (from
sending the POST to reading the status): median, 95th percentile, maximum, and votes with no
answer within 10 s, and the server's CPU time per request (user and system, from /proc: what it
costs whatever else the machine runs; a shared machine's load stretches the waits, not this).
The median over the runs of each figure closes the report.

  --server poll      sandbox-cli poll (Boost.Beast on Asio, one thread), step 2 of the fixture
  --server httplib   cpp-httplib 0.11.4, thread pool (tests/bench/poll_servers, poll_bench.sh)
  --server civetweb  civetweb 1.15, 50 worker threads (same)

With --slow N, N more connections send a request's header a byte a second while the phones
vote (a slow network, or someone holding the server's connections on purpose).

usage: poll_bench.py [--server poll|httplib|civetweb] [--cli BUILD/app/cli/sandbox-cli]
                     [--bin DIR] [--idle 1000] [--phones 300] [--slow 0] [--runs 5]
"""
import argparse
import asyncio
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "poll"))
from poll_client import PollServer, proc_status, read_response  # noqa: E402

ANSWER_GUARD_S = 10.0


class Target:
    def __init__(self, args):
        self.kind = args.server
        if self.kind == "poll":
            lesson = os.path.join(HERE, "..", "data", "poll", "poll_lesson.json")
            self.server = PollServer(args.cli, lesson)
            self.server.command("open 2")
            self.pid, self.port = self.server.proc.pid, self.server.port
            self.base = "/" + self.server.token
        else:
            self.proc = subprocess.Popen([os.path.join(args.bin, self.kind + "_server")],
                                         stdout=subprocess.PIPE, text=True)
            self.port = int(self.proc.stdout.readline())
            self.pid, self.base = self.proc.pid, "/t"
        self.host = "127.0.0.1:%d" % self.port

    def stop(self):
        if self.kind == "poll":
            self.server.quit()
        else:
            self.proc.kill()
            self.proc.wait()


async def send(reader, writer, target, method, path, body=b""):
    head = "%s %s HTTP/1.1\r\nHost: %s\r\n" % (method, path, target.host)
    if method == "POST":
        head += ("Content-Type: application/json\r\nOrigin: http://%s\r\n"
                 "Content-Length: %d\r\n" % (target.host, len(body)))
    writer.write(head.encode() + b"\r\n" + body)
    await writer.drain()
    return (await asyncio.wait_for(read_response(reader), ANSWER_GUARD_S))[0]


async def idle_phone(target, i, held):
    reader, writer = await asyncio.open_connection("127.0.0.1", target.port)
    try:
        await send(reader, writer, target, "GET",
                   "%s/state?device=idle-%06d" % (target.base, i))
    except (asyncio.TimeoutError, ConnectionError):
        pass
    held.append(writer)


async def voting_phone(target, i):
    device = "vote-%06d" % i
    try:
        reader, writer = await asyncio.wait_for(
            asyncio.open_connection("127.0.0.1", target.port), ANSWER_GUARD_S)
        await send(reader, writer, target, "GET", "%s/state?device=%s" % (target.base, device))
        body = json.dumps({"device": device, "choice": i % 3}).encode()
        start = time.perf_counter()
        status = await send(reader, writer, target, "POST", target.base + "/vote", body)
        elapsed = time.perf_counter() - start
        writer.close()
        return elapsed if status == 204 else None
    except (asyncio.TimeoutError, ConnectionError, OSError):
        return None


def cpu_seconds(pid):
    """The process's user and system CPU time so far (s), from /proc: what the server spent,
    whatever else the machine runs."""
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


async def slow_phone(target, stop):
    """A connection that sends a request's header a byte a second (a slow or hostile client)."""
    try:
        reader, writer = await asyncio.open_connection("127.0.0.1", target.port)
        for byte in ("GET %s/state HTTP/1.1\r\nHost: %s\r\nX-Slow: %s\r\n\r\n"
                     % (target.base, target.host, "s" * 60)).encode():
            if stop.is_set():
                break
            writer.write(bytes([byte]))
            await writer.drain()
            try:
                await asyncio.wait_for(stop.wait(), 1.0)
            except asyncio.TimeoutError:
                pass
        writer.close()
    except (ConnectionError, OSError):
        pass


async def one_run(target, idle, phones, slow=0):
    held = []
    stop = asyncio.Event()
    slow_tasks = [asyncio.ensure_future(slow_phone(target, stop)) for _ in range(slow)]
    await asyncio.sleep(1.0 if slow else 0)
    # Idle phones connect in batches (a class arriving, not one SYN flood).
    for start in range(0, idle, 100):
        await asyncio.gather(*(idle_phone(target, i, held)
                               for i in range(start, min(idle, start + 100))))
    threads, rss = proc_status(target.pid)
    cpu0 = cpu_seconds(target.pid)
    times = await asyncio.gather(*(voting_phone(target, i) for i in range(phones)))
    cpu = cpu_seconds(target.pid) - cpu0
    stop.set()
    await asyncio.gather(*slow_tasks)
    for w in held:
        w.close()
    answered = sorted(t for t in times if t is not None)
    p95 = answered[max(0, int(round(0.95 * len(answered))) - 1)] if answered else float("nan")
    return {"threads": threads, "rss_mib": rss / 1024,
            "p50_ms": 1000 * statistics.median(answered) if answered else float("nan"),
            "p95_ms": 1000 * p95, "max_ms": 1000 * answered[-1] if answered else float("nan"),
            "unanswered": phones - len(answered),
            "cpu_us_per_request": 1e6 * cpu / (2 * phones)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--server", default="poll", choices=["poll", "httplib", "civetweb"])
    parser.add_argument("--cli", default=os.path.join(HERE, "..", "..", "build", "app", "cli",
                                                      "sandbox-cli"))
    parser.add_argument("--bin", default=os.path.join(HERE, "..", "..", "build", "poll_servers"))
    parser.add_argument("--idle", type=int, default=1000)
    parser.add_argument("--phones", type=int, default=300)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--slow", type=int, default=0,
                        help="connections trickling a header a byte a second meanwhile")
    args = parser.parse_args()
    results = []
    for run in range(args.runs):
        target = Target(args)
        try:
            r = asyncio.run(one_run(target, args.idle, args.phones, args.slow))
        finally:
            target.stop()
        results.append(r)
        print("run %d: %s" % (run + 1, json.dumps({k: round(v, 2) for k, v in r.items()})),
              flush=True)
    print("median of %d runs, %s, %d idle phones held, %d trickling, %d voting: %s" % (
        args.runs, args.server, args.idle, args.slow, args.phones,
        json.dumps({k: round(statistics.median(r[k] for r in results), 2)
                    for k in results[0]})))


if __name__ == "__main__":
    main()
