#!/usr/bin/env python3
"""Measures the share of UDP datagrams that arrive between two hosts of deploy/hosts.sh, to check
that nftables' `numgen random mod 100 < N drop` drops what was asked (there is no ping here).

  udp_loss.py recv PORT COUNT        prints how many of COUNT numbered datagrams arrived
  udp_loss.py send ADDR PORT COUNT   sends COUNT numbered datagrams, paced so none is lost to buffers
"""
import socket
import sys
import time


def recv(port, count):
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4 << 20)
    s.bind(("0.0.0.0", port))
    s.settimeout(3.0)  # the sender is done when nothing came for 3 s
    seen = set()
    try:
        while True:
            data, _ = s.recvfrom(64)
            n = int(data)
            if n >= 0:
                seen.add(n)
    except socket.timeout:
        pass
    print(f"received {len(seen)} of {count}: {100.0 * (count - len(seen)) / count:.2f} % lost")


def send(addr, port, count):
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    for n in range(count):
        s.sendto(str(n).encode(), (addr, port))
        if n % 200 == 199:
            time.sleep(0.002)


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "recv":
        recv(int(sys.argv[2]), int(sys.argv[3]))
    elif len(sys.argv) == 5 and sys.argv[1] == "send":
        send(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
    else:
        sys.exit(__doc__)
