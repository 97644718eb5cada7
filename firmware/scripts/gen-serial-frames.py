#!/usr/bin/env python3
"""Writes tests/vectors/serial-frames.json, the golden serial frames of
docs/protocol.md section 7. The CRC here is computed independently of the
C++ and TypeScript codecs, which must both reproduce these bytes."""
import json
import os
import struct
import sys


def crc16_ccitt_false(data: bytes) -> int:
    crc = 0xFFFF
    for byte in data:
        crc ^= byte << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1021) if crc & 0x8000 else (crc << 1)
            crc &= 0xFFFF
    return crc


def frame(ftype: int, seq: int, payload: bytes) -> bytes:
    n = len(payload)
    head = bytes([0xA5, 0x5A, ftype]) + struct.pack("<HHH", seq, n, n ^ 0xFFFF)
    body = head + payload
    return body + struct.pack(">H", crc16_ccitt_false(body))


def valid(name, ftype, seq, payload_text):
    payload = payload_text.encode("utf-8")
    return {
        "name": name,
        "hex": frame(ftype, seq, payload).hex(),
        "decoded": {"type": "data" if ftype == 1 else "ack", "seq": seq,
                    "payload": payload_text},
    }


def main():
    assert crc16_ccitt_false(b"123456789") == 0x29B1
    pad = "x" * (1024 - len('{"cmd":"get_status","pad":""}'))
    big = '{"cmd":"get_status","pad":"' + pad + '"}'
    assert len(big.encode()) == 1024
    frames = [
        valid("data_hello", 1, 1, '{"cmd":"hello","seq":1,"client":"hal-physical"}'),
        valid("data_seed_move_steps", 1, 2,
              '{"cmd":"move_steps","left":1000,"right":1000,"speed":500}'),
        valid("ack_seq_2", 2, 2, ""),
        valid("data_reply", 1, 0x1234,
              '{"seq":7,"sid":305419896,"ok":true,"cmd":"heartbeat","uptime_ms":1500,"running":false,"estop":false}'),
        valid("data_empty_payload", 1, 5, ""),
        valid("data_seq_ffff", 1, 0xFFFF, '{"cmd":"stop"}'),
        valid("data_utf8_payload", 1, 9, '{"cmd":"estop","reason":"bumper \u00e9\u00e8 \u2713"}'),
        valid("data_max_payload_1024", 1, 10, big),
    ]
    good = bytes.fromhex(frames[1]["hex"])
    bad_crc = bytearray(good)
    bad_crc[-1] ^= 0x01
    bad_len = bytearray(good)
    bad_len[7] ^= 0x01
    bad_type = bytearray(good)
    bad_type[2] = 0x03
    oversize = bytes([0xA5, 0x5A, 0x01]) + struct.pack("<HHH", 3, 1025, 1025 ^ 0xFFFF)
    ack_payload = bytearray(frame(2, 4, b"x"))
    frames += [
        {"name": "bad_crc_last_bit", "hex": bytes(bad_crc).hex(), "error": "bad_crc"},
        {"name": "bad_length_inverse", "hex": bytes(bad_len).hex(), "error": "bad_length"},
        {"name": "bad_type_0x03", "hex": bytes(bad_type).hex(), "error": "bad_type"},
        {"name": "oversize_1025", "hex": oversize.hex(), "error": "oversize"},
        {"name": "ack_with_payload", "hex": bytes(ack_payload).hex(), "error": "bad_length"},
        {"name": "truncated", "hex": good[:-3].hex(), "error": "incomplete"},
        {"name": "bad_sync", "hex": (b"\x5a\xa5" + good[2:]).hex(), "error": "bad_sync"},
    ]
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(__file__), "..", "..", "tests", "vectors", "serial-frames.json")
    with open(out, "w", encoding="utf-8") as f:
        json.dump(frames, f, indent=2, ensure_ascii=False)
        f.write("\n")


if __name__ == "__main__":
    main()
