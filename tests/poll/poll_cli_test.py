#!/usr/bin/python3
"""sandbox-cli poll through its real server, bound to 127.0.0.1 (issue 40). One check per run:

  votes        300 simulated phones on their own connections, all at once: most vote once, some
               change their vote, some vote twice the same, some only look, some vote after the
               close (409); `close` prints the counts exactly as expected; a second round ("Vote
               again") counts apart, and the CSV keeps both
  refusals     a wrong or missing token (403), a foreign or missing Host (421), a cross-site POST
               (403), a form's content type (415), a body over the cap (413), headers over the
               cap (431), a choice out of range (422), malformed JSON and a malformed request
               (400), a flood from one device (429): none changes a count or stops the server
  trickle      a request's headers sent a byte at a time are dropped before they end (the server
               closes the connection unanswered) and the server goes on
  connections  1,000 phones hold open connections: the server keeps its thread count and its
               resident memory within a bound, and answers each of them again
  lesson       bad lessons, steps and commands: an error naming them, the server going on

The first four serve lessons/lecture3.json and vote on its step 18 (three choices, B the one the
run proves, read through the lesson library); `lesson` serves the fixture tests/data/poll.

usage: poll_cli_test.py SANDBOX_CLI LESSON CHECK
Exit 0 passed, 1 failed. Timeouts only guard against a hang; nothing is timed.
"""
import asyncio
import json
import os
import random
import socket
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poll_client import Phone, PollServer, proc_status, run_test  # noqa: E402

STEP = 18  # lecture3's "Move and correct: the mess": three choices, B proved by the run
CHOICES = 3


def check(condition, message):
    if not condition:
        raise AssertionError(message)


async def run_phones(server, plan):
    """plan: {device: [choice, ...]}: each phone joins (GET state) then casts its votes in
    order on its own connection, all phones at once. Returns {device: [status, ...]}."""
    async def one(device, votes):
        phone = Phone(server, device)
        try:
            status, view = await phone.state()
            check(status == 200 and view["open"], "%s: state %s %s" % (device, status, view))
            return device, [await phone.vote(c) for c in votes]
        finally:
            phone.close()
    return dict(await asyncio.gather(*(one(d, v) for d, v in plan.items())))


def votes_check(server):
    rng = random.Random(40)
    check(server.command("open %d" % STEP) == {"step": STEP, "round": 1, "open": True,
                                               "choices": 3}, "open %d" % STEP)
    plan, expected = {}, [0] * CHOICES
    for i in range(300):
        device = "phone-%04d" % i
        kind = i % 10
        first = rng.randrange(CHOICES)
        if kind < 5:                       # once
            votes = [first]
        elif kind < 7:                     # changes its vote
            votes = [first, (first + 1 + rng.randrange(CHOICES - 1)) % CHOICES]
        elif kind < 8:                     # twice the same
            votes = [first, first]
        elif kind < 9:                     # changes it twice
            votes = [first, (first + 1) % CHOICES, (first + 2) % CHOICES]
        else:                              # only looks, votes after the close
            votes = []
        plan[device] = votes
        if votes:
            expected[votes[-1]] += 1
    statuses = asyncio.run(run_phones(server, plan))
    for device, votes in plan.items():
        check(statuses[device] == [204] * len(votes), "%s: %s" % (device, statuses[device]))
    status = server.command("status")
    check(status["joined"] == 300 and status["voted"] == 270 and status["open"], status)
    closed = server.command("close")
    print("close:", closed)
    check(closed == {"step": STEP, "round": 1, "counts": expected, "voters": 270, "proved": 1},
          "close: %s, expected counts %s" % (closed, expected))
    # After the close: refused, not counted.
    late = {d: [1] for d in list(plan)[9::10]}
    late["phone-0000"] = [2]

    async def after_close():
        out = {}
        for device, votes in late.items():
            phone = Phone(server, device)
            out[device] = [await phone.vote(c) for c in votes]
            phone.close()
        return out
    for device, codes in asyncio.run(after_close()).items():
        check(codes == [409], "%s after close: %s" % (device, codes))
    check(server.command("close") == {"error": "no vote is open"}, "a second close")
    check(server.command("revote") == {"step": STEP, "round": 2, "open": True}, "revote")
    check(server.command("revote") == {"error": "revote: the vote is still open"}, "revote twice")
    check(server.command("close")["counts"] == [0, 0, 0], "an empty round")
    # Vote again: a third round, counted apart.
    check(server.command("revote") == {"step": STEP, "round": 3, "open": True}, "revote")
    second = {"phone-%04d" % i: [i % CHOICES] for i in range(30)}
    statuses = asyncio.run(run_phones(server, second))
    check(all(s == [204] for s in statuses.values()), "round 2: %s" % statuses)
    closed2 = server.command("close")
    check(closed2 == {"step": STEP, "round": 3, "counts": [10, 10, 10], "voters": 30, "proved": 1},
          "round 2: %s" % closed2)
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "poll.csv")
        check(server.command("save " + path) == {"saved": path}, "save")
        with open(path) as f:
            rows = f.read().splitlines()
    check(rows[0] == "step,round,choice,text,count,voters,proved,question", rows[0])
    check(len(rows) == 1 + 3 * CHOICES, rows)
    # The choices as the lesson shows them, computed from the step's world ("{top.top0}": 5).
    check(rows[2].startswith('%d,1,B,"Lower: the stack sinks into itself",%d,270,yes,'
                             % (STEP, expected[1])), rows[2])
    check(rows[4].startswith('%d,2,A,"At 5 m, at rest: nothing should move",0,0,no,' % STEP),
          rows[4])
    check(rows[7].startswith('%d,3,A,"At 5 m, at rest: nothing should move",10,30,no,' % STEP),
          rows[7])


async def raw_exchange(server, data):
    """Sends raw bytes on a new connection; returns the status code, or None when the server
    closed without answering."""
    reader, writer = await asyncio.open_connection("127.0.0.1", server.port)
    try:
        writer.write(data)
        await writer.drain()
        line = await asyncio.wait_for(reader.readline(), 60)
        return int(line.split()[1]) if line else None
    finally:
        writer.close()


def refusals_check(server):
    server.command("open %d" % STEP)

    async def refusals():
        t, host = server.token, server.host
        phone = Phone(server, "phone-good")
        check(await phone.vote(0) == 204, "a good vote")
        results = {}
        p = Phone(server, "phone-attack")
        json_headers = {"Content-Type": "application/json", "Origin": "http://" + host}
        good = b'{"device": "phone-attack", "choice": 1}'
        results["wrong token"] = (await p.request("GET", "/23456789abcd/state"))[0], 403
        results["wrong token vote"] = (await p.request("POST", "/23456789abcd/vote", good,
                                                       json_headers))[0], 403
        results["missing token"] = (await p.request("GET", "/"))[0], 403
        results["missing token vote"] = (await p.request("POST", "/vote", good,
                                                         json_headers))[0], 403
        results["foreign host"] = (await p.request("POST", "/%s/vote" % t, good, json_headers,
                                                   host="attacker.example"))[0], 421
        results["foreign port"] = (await p.request("GET", "/%s/state" % t,
                                                   host="127.0.0.1:1"))[0], 421
        async def vote_status(body, headers):
            """The status of a vote with this body and these headers, through the good token."""
            return (await p.request("POST", "/%s/vote" % t, body, headers))[0]

        results["cross-site origin"] = await vote_status(
            good, {"Content-Type": "application/json", "Origin": "http://attacker.example"}), 403
        results["cross-site fetch"] = await vote_status(
            good, {"Content-Type": "application/json", "Sec-Fetch-Site": "cross-site"}), 403
        results["form"] = await vote_status(
            good, {"Content-Type": "text/plain", "Origin": "http://" + host}), 415
        results["out of range"] = await vote_status(
            b'{"device": "phone-attack", "choice": 3}', json_headers), 422
        results["negative"] = await vote_status(
            b'{"device": "phone-attack", "choice": -1}', json_headers), 422
        results["malformed json"] = await vote_status(
            b'{"device": "phone-attack", "choice": ', json_headers), 400
        results["free text"] = await vote_status(
            b'{"device": "phone-attack", "choice": 1, "name": "Ann"}', json_headers), 400
        p.close()
        # On connections of their own (the server closes them after refusing).
        results["body over the cap"] = await raw_exchange(
            server, ("POST /%s/vote HTTP/1.1\r\nHost: %s\r\nContent-Type: application/json\r\n"
                     "Content-Length: 5000\r\n\r\n" % (t, host)).encode() + b"x" * 5000), 413
        results["headers over the cap"] = await raw_exchange(
            server, ("GET /%s/state HTTP/1.1\r\nHost: %s\r\nX-Pad: %s\r\n\r\n"
                     % (t, host, "p" * 8000)).encode()), 431
        results["not http"] = await raw_exchange(server, b"\x16\x03\x01\x02\x00\x01\x00\r\n\r\n"), 400
        results["no host"] = await raw_exchange(
            server, ("GET /%s/state HTTP/1.0\r\n\r\n" % t).encode()), 421
        # A flood from one device: the first kPollBurst pass, then 429.
        flood = Phone(server, "phone-flood")
        codes = [await flood.vote(0) for _ in range(60)]
        flood.close()
        check(codes[0] == 204 and 429 in codes, "flood: %s" % codes)
        results["flood"] = 429, 429
        for name, (got, want) in results.items():
            check(got == want, "%s: %s, expected %s" % (name, got, want))
        # The server goes on: another device votes, the page is still served.
        check(await Phone(server, "phone-after").vote(2) == 204, "a vote after the refusals")
        status, _, page = await Phone(server, "x").request("GET", "/%s/" % t)
        check(status == 200 and b"poll.js" in page, "the page after the refusals")
    asyncio.run(refusals())
    closed = server.command("close")
    check(closed["counts"] == [2, 0, 1] and closed["voters"] == 3, "counts: %s" % closed)


def trickle_check(server):
    request = ("GET /%s/state?device=phone-trickle HTTP/1.1\r\nHost: %s\r\nUser-Agent: %s\r\n\r\n"
               % (server.token, server.host, "slow" * 20)).encode()
    s = socket.create_connection(("127.0.0.1", server.port), timeout=60)
    dropped_at = None
    try:
        for i, byte in enumerate(request):
            try:
                s.sendall(bytes([byte]))
            except OSError:
                dropped_at = i
                break
            time.sleep(0.25)  # a byte every 250 ms: the request would take 30 s
            s.setblocking(False)
            try:
                if s.recv(1024) == b"":
                    dropped_at = i
                    break
                raise AssertionError("the server answered a request it had not read whole")
            except BlockingIOError:
                pass
            except ConnectionResetError:
                dropped_at = i
                break
            finally:
                s.setblocking(True)
    finally:
        s.close()
    check(dropped_at is not None, "a trickled request was never dropped")
    print("dropped after %d of %d bytes" % (dropped_at + 1, len(request)))
    server.command("open %d" % STEP)
    check(asyncio.run(Phone(server, "phone-after").vote(1)) == 204, "the server after a trickle")


def connections_check(server):
    server.command("open %d" % STEP)
    threads0, rss0 = proc_status(server.proc.pid)

    async def hold():
        phones = [Phone(server, "phone-%05d" % i) for i in range(1000)]
        for i in range(0, 1000, 100):  # connect in batches: the listen queue is not the test
            await asyncio.gather(*(p.connect() for p in phones[i:i + 100]))
        states = await asyncio.gather(*(p.state() for p in phones))
        check(all(s == 200 for s, _ in states), "every phone joined")
        held = proc_status(server.proc.pid)
        # Each phone again on its own still-open connection: all 1,000 were held.
        again = await asyncio.gather(*(p.vote(i % CHOICES) for i, p in enumerate(phones)))
        check(all(s == 204 for s in again), "a connection was dropped: %s" % set(again))
        for p in phones:
            p.close()
        return held
    threads1, rss1 = asyncio.run(hold())
    print("threads %d -> %d, resident %.1f MiB -> %.1f MiB (%.1f KiB per connection)"
          % (threads0, threads1, rss0 / 1024, rss1 / 1024, (rss1 - rss0) / 1000))
    check(threads1 == threads0, "threads %d with 1,000 phones, %d before" % (threads1, threads0))
    check(threads1 <= 3, "%d threads" % threads1)
    if os.environ.get("SANDBOX_POLL_SANITIZED") != "1":  # ASan's shadow memory is not the poll's
        check(rss1 - rss0 < 16 * 1024,
              "resident memory grew %d kB for 1,000 phones" % (rss1 - rss0))
    closed = server.command("close")
    check(closed["voters"] == 1000 and sum(closed["counts"]) == 1000, closed)


def lesson_check(cli, lesson):
    import subprocess
    bad = subprocess.run([cli, "poll", lesson + ".missing", "--bind", "127.0.0.1"],
                         capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=60)
    check(bad.returncode == 1 and "no such file" in bad.stderr, bad.stderr)
    bad = subprocess.run([cli, "poll", lesson, "--bind", "127.0.0.1", "--port", "70000"],
                         capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=60)
    check(bad.returncode == 1 and "--port" in bad.stderr, bad.stderr)
    bad = subprocess.run([cli, "poll", lesson, "--bind", "not-an-address"],
                         capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=60)
    check(bad.returncode == 1 and "not an IP address" in bad.stderr, bad.stderr)
    # A question with five choices: the lesson library refuses the file, naming the place.
    with tempfile.TemporaryDirectory() as tmp:
        with open(lesson) as f:
            five = json.load(f)
        five["steps"][1]["choices"] += [{"text": "Four", "if": "t < 0"},
                                        {"text": "Five", "if": "t < 0"}]
        path = os.path.join(tmp, "five.json")
        with open(path, "w") as f:
            json.dump(five, f)
        bad = subprocess.run([cli, "poll", path, "--bind", "127.0.0.1"], capture_output=True,
                             text=True, stdin=subprocess.DEVNULL, timeout=60)
    check(bad.returncode == 1 and "steps[1].choices" in bad.stderr
          and "2 to 4 choices, not 5" in bad.stderr, bad.stderr)
    server = PollServer(cli, lesson)
    try:
        check("asks nothing" in server.command("open 1")["error"], "step 1")
        check("no step 9" in server.command("open 9")["error"], "step 9")
        check("open STEP" in server.command("open x")["error"], "open x")
        check("unknown command" in server.command("vote 2")["error"], "vote 2")
        check("no question is asked" in server.command("revote")["error"], "revote")
        check(server.command("open 3")["choices"] == 4, "open 3")
        check(server.command("status")["open"], "status")
        check(server.quit() == 0, "quit")
    finally:
        server.kill()


def main():
    cli, lesson, name = sys.argv[1:4]
    if name == "lesson":
        lesson_check(cli, lesson)
        print("passed")
        return 0
    server = PollServer(cli, lesson)
    try:
        {"votes": votes_check, "refusals": refusals_check, "trickle": trickle_check,
         "connections": connections_check}[name](server)
        check(server.alive(), "the server stopped")
        check(server.quit() == 0, "quit")
    finally:
        server.kill()
    print("passed")
    return 0


if __name__ == "__main__":
    run_test(main)
