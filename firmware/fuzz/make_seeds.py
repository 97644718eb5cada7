#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora from the golden vectors
(tests/vectors/protocol-messages.json and serial-frames.json), so the seeds
follow the vectors and nothing is copied into the repository.

usage: make_seeds.py VECTORS_DIR OUT_DIR
Creates OUT_DIR/<target>/ for json_reader, cube_keyless, cube_keyed and
deframer (the input formats are described at the top of each target).
"""
import hashlib
import json
import os
import sys

SEPARATOR = b"\x1e"
ADVANCE_MS = [0, 1, 20, 100, 300, 800, 1500, 2500]


def compact(obj):
    return json.dumps(obj, separators=(",", ":"), ensure_ascii=False).encode()


def write(out_dir, target, data):
    folder = os.path.join(out_dir, target)
    os.makedirs(folder, exist_ok=True)
    name = hashlib.sha1(data).hexdigest()
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def control(step, sign):
    """The control byte of one request: sign bit, time to let pass first."""
    ctl = 1 if sign else 0
    ms = step.get("advance_ms", 0)
    if ms:
        index = next((i for i, v in enumerate(ADVANCE_MS) if v >= ms), 7)
        ctl |= index << 2 | 0x20  # with the host keeping the link alive
    return ctl


def request_bytes(step):
    return step["send_raw"].encode() if "send_raw" in step else compact(step["send"])


def parts_of(step, sign):
    """One step as requests; a wait longer than the longest the control
    byte can give is split over heartbeats sent before it."""
    parts = []
    ms = step.get("advance_ms", 0)
    while ms > ADVANCE_MS[-1]:
        wait = {"advance_ms": ADVANCE_MS[-1]}
        parts.append(bytes([control(wait, sign)]) + b'{"cmd":"heartbeat"}')
        ms -= ADVANCE_MS[-1]
    rest = dict(step, advance_ms=ms)
    parts.append(bytes([control(rest, sign)]) + request_bytes(step))
    return parts


def cube_seeds(cases, out_dir, target, sign):
    for case in cases:
        parts = [p for s in case["steps"] for p in parts_of(s, sign)]
        write(out_dir, target, b"\x00" + SEPARATOR.join(parts))
        # The same requests as retries, from an open session.
        retried = [bytes([p[0] | 2]) + p[1:] for p in parts]
        write(out_dir, target, b"\x01" + SEPARATOR.join(retried))


def main():
    vectors, out_dir = sys.argv[1], sys.argv[2]
    with open(os.path.join(vectors, "protocol-messages.json")) as f:
        cases = json.load(f)["cases"]
    with open(os.path.join(vectors, "serial-frames.json")) as f:
        frames = json.load(f)

    for case in cases:
        for step in case["steps"]:
            write(out_dir, "json_reader", request_bytes(step))
    for fr in frames:
        if "decoded" in fr and fr["decoded"]["payload"]:
            write(out_dir, "json_reader", fr["decoded"]["payload"].encode())

    cube_seeds(cases, out_dir, "cube_keyless", sign=False)
    cube_seeds(cases, out_dir, "cube_keyed", sign=True)

    # Each frame alone, then all of them in one stream with garbage between,
    # cut differently and with stalls (seed byte bit 7).
    stream = b""
    for i, fr in enumerate(frames):
        raw = bytes.fromhex(fr["hex"])
        write(out_dir, "deframer", bytes([i]) + raw)
        stream += raw + b"\xa5garbage\x5a"
    write(out_dir, "deframer", b"\x07" + stream)
    write(out_dir, "deframer", b"\x85" + stream)
    return 0


if __name__ == "__main__":
    sys.exit(main())
