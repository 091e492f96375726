#!/usr/bin/python3
"""A Foxglove WebSocket client that subscribes to every channel and then stops reading (tools/bench/live_cost.sh).

    live_stalled_client.py PORT [SECONDS]

Connects to ws://127.0.0.1:PORT (retrying until the server listens, at most SECONDS), performs the handshake with
subprotocol foxglove.websocket.v1, reads serverInfo and advertise, subscribes to every advertised channel, prints
"STALLED N" (N channels) and then never reads again: the server's sends fill the socket buffers (a 4 KiB receive
buffer, so that they fill early) and its per-client limit, after which gdnav drops the frames for this client.
Exits when killed or after SECONDS.
"""
import json
import os
import socket
import struct
import sys
import time

port = int(sys.argv[1])
deadline = time.time() + float(sys.argv[2] if len(sys.argv) > 2 else 300)


def connect():
    while time.time() < deadline:
        s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        # A small receive buffer (set before connecting, so the window is small from the start): the server's
        # per-client limit, not the kernel's buffers, decides when the client is stalled, even in short runs.
        s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        s.settimeout(5)
        try:
            s.connect(("127.0.0.1", port))
            return s
        except OSError:
            s.close()
            time.sleep(0.02)
    sys.exit("live_stalled_client: no server on port %d" % port)


def read_exact(s, n):
    b = b""
    while len(b) < n:
        chunk = s.recv(n - len(b))
        if not chunk:
            sys.exit("live_stalled_client: connection closed")
        b += chunk
    return b


def read_frame(s):
    h = read_exact(s, 2)
    n = h[1] & 0x7F
    if n == 126:
        n = struct.unpack(">H", read_exact(s, 2))[0]
    elif n == 127:
        n = struct.unpack(">Q", read_exact(s, 8))[0]
    return h[0] & 0x0F, read_exact(s, n)


def send_text(s, text):
    data = text.encode()
    mask = os.urandom(4)
    head = bytes([0x81])
    head += bytes([0x80 | len(data)]) if len(data) < 126 else bytes([0x80 | 126]) + struct.pack(">H", len(data))
    s.sendall(head + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(data)))


s = connect()
s.sendall(("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
           "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n"
           "Sec-WebSocket-Protocol: foxglove.websocket.v1\r\n\r\n").encode())
response = b""
while b"\r\n\r\n" not in response:
    response += read_exact(s, 1)
if not response.startswith(b"HTTP/1.1 101"):
    sys.exit("live_stalled_client: handshake refused: " + response.decode(errors="replace"))
ids = []
while not ids:
    op, payload = read_frame(s)
    if op == 1 and json.loads(payload).get("op") == "advertise":
        ids = [c["id"] for c in json.loads(payload)["channels"]]
send_text(s, json.dumps({"op": "subscribe", "subscriptions": [{"id": i, "channelId": c} for i, c in enumerate(ids)]}))
print("STALLED %d" % len(ids), flush=True)
while time.time() < deadline:
    time.sleep(0.2)
