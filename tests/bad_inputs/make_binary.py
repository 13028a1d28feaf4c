#!/usr/bin/env python3
"""Writes the corpus's binary_garbage.* files: the same 320 bytes for every loader, a fixed pattern
of bytes 0x80-0xff (none is valid UTF-8 as it stands: no lead byte is followed by its continuation
bytes in order, and there is no line break, comma or white space). The files are in git; run this
again only to recreate them: python3 tests/bad_inputs/make_binary.py"""
import os

GARBAGE = bytes(0x80 + (i * 37 + 11) % 128 for i in range(320))
FILES = [
    "keyframes/binary_garbage.json",
    "nearest_neighbor/binary_garbage.json",
    "wang2009/binary_garbage.json",
    "wang2012/binary_garbage.json",
    "trajectory_csv/binary_garbage.csv",
    "checkpoint/binary_garbage.ckpt",
    "normative_gait/binary_garbage.csv",
]

if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    for f in FILES:
        path = os.path.join(here, f)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as out:
            out.write(GARBAGE)
