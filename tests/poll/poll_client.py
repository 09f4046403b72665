"""Simulated phones for the class poll's tests and benchmark: sandbox-cli poll as a child
process (its stdin commands, its JSON lines), and a small HTTP/1.1 client on asyncio streams (one
keep-alive connection per phone). Every request goes to 127.0.0.1: the server is bound there.
Timeouts only guard against a hang; nothing is timed."""
import asyncio
import json
import select
import subprocess
import sys

HANG_GUARD_S = 60


class PollServer:
    """sandbox-cli poll LESSON --bind 127.0.0.1, driven through stdin."""

    def __init__(self, cli, lesson, *extra):
        self.proc = subprocess.Popen([cli, "poll", lesson, "--bind", "127.0.0.1", *extra],
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        first = self._line()
        self.url, self.token, self.port = first["url"], first["token"], first["port"]
        self.host = "127.0.0.1:%d" % self.port
        assert first["address"] == "127.0.0.1", first
        assert self.url == "http://%s/%s" % (self.host, self.token), first

    def _line(self):
        ready, _, _ = select.select([self.proc.stdout], [], [], HANG_GUARD_S)
        if not ready:
            self.proc.kill()
            raise RuntimeError("sandbox-cli poll: no answer (hung)")
        line = self.proc.stdout.readline()
        if not line:
            raise RuntimeError("sandbox-cli poll ended (exit %s)" % self.proc.wait())
        return json.loads(line)

    def command(self, line):
        self.proc.stdin.write(line + "\n")
        self.proc.stdin.flush()
        return self._line()

    def alive(self):
        return self.proc.poll() is None

    def quit(self):
        self.proc.stdin.write("quit\n")
        self.proc.stdin.flush()
        return self.proc.wait(timeout=HANG_GUARD_S)

    def kill(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()


class Phone:
    """One keep-alive connection to the poll."""

    def __init__(self, server, device):
        self.server = server
        self.device = device
        self.reader = self.writer = None

    async def connect(self):
        self.reader, self.writer = await asyncio.wait_for(
            asyncio.open_connection("127.0.0.1", self.server.port), HANG_GUARD_S)

    async def request(self, method, path, body=b"", headers=None, host=None):
        """Sends one request on this connection; returns (status, headers, body)."""
        if self.writer is None:
            await self.connect()
        head = ["%s %s HTTP/1.1" % (method, path), "Host: %s" % (host or self.server.host)]
        for name, value in (headers or {}).items():
            head.append("%s: %s" % (name, value))
        if body or method == "POST":
            head.append("Content-Length: %d" % len(body))
        self.writer.write(("\r\n".join(head) + "\r\n\r\n").encode() + body)
        await self.writer.drain()
        return await asyncio.wait_for(read_response(self.reader), HANG_GUARD_S)

    async def state(self):
        status, _, body = await self.request(
            "GET", "/%s/state?device=%s" % (self.server.token, self.device))
        return status, json.loads(body) if status == 200 else None

    async def vote(self, choice, device=None):
        body = json.dumps({"device": device or self.device, "choice": choice}).encode()
        status, _, _ = await self.request(
            "POST", "/%s/vote" % self.server.token, body,
            {"Content-Type": "application/json", "Origin": "http://" + self.server.host,
             "Sec-Fetch-Site": "same-origin"})
        return status

    def close(self):
        if self.writer is not None:
            self.writer.close()
            self.writer = None


async def read_response(reader):
    status_line = await reader.readline()
    if not status_line:
        raise ConnectionError("closed by the server")
    status = int(status_line.split()[1])
    headers = {}
    while True:
        line = await reader.readline()
        if line in (b"\r\n", b"\n", b""):
            break
        name, _, value = line.decode("latin-1").partition(":")
        headers[name.strip().lower()] = value.strip()
    body = await reader.readexactly(int(headers.get("content-length", "0")))
    return status, headers, body


def proc_status(pid):
    """Threads and resident memory (kB) of a process, from /proc."""
    fields = {}
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            name, _, value = line.partition(":")
            fields[name] = value.strip()
    return int(fields["Threads"]), int(fields["VmRSS"].split()[0])


def run_test(main):
    """Exits with what a test's main() returns, or 1 with the check that failed said."""
    try:
        sys.exit(main())
    except AssertionError as e:
        print("FAILED:", e)
        sys.exit(1)
