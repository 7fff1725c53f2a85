#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Writes the binary twins of cameras.3dmf and pixmap_marker.3dmf, laid out
# field by field as Apple's metafile parser (MF3D) and the 3D Metafile
# Reference describe cameras, and as Quesa reads a PixmapMarker: big-endian
# as Mac QuickDraw 3D wrote them, and little-endian.
# Run from anywhere: python3 tests/data/make_camera_binary.py
import os

from mf3d import floats, header, ints, obj, uns, write_both

here = os.path.dirname(os.path.abspath(__file__))


def camera(order, tag, own, placement, camera_range, view_port):
    return obj(order, b"cntr", obj(order, tag, floats(order, *own))
               + obj(order, b"cmpl", floats(order, *placement))
               + obj(order, b"cmrg", floats(order, *camera_range))
               + obj(order, b"cmvp", floats(order, *view_port)))


def cameras_file(order):
    # The cameras of cameras.3dmf.
    return (header(order)
            + camera(order, b"vana", [0.5235988, 1.5], [2, 3, 10, 0, 0.5, 0, 0, 1, 0], [0.5, 50], [-1, 1, 2, 2])
            + camera(order, b"orth", [-4, 3, 4, -3], [0, 0, 8, 0, 0, 0, 0, 1, 0], [0, 20], [-0.5, 0.5, 1, 1])
            + camera(order, b"vwpl", [5, 2, 1.5, 0.25, -0.5], [0, 5, 5, 0, 0, 0, 0, 0, -1], [1, 100], [-1, 1, 2, 2])
            + obj(order, b"vana", floats(order, 1, 1)))


def pixmap_marker_file(order):
    # The marker of pixmap_marker.3dmf: 3 x 2 RGB24 pixels, rows of 12 bytes
    # (9 used), 24 bytes of image; red, green, blue over white, black, grey.
    image = bytes([255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0,
                   255, 255, 255, 0, 0, 0, 128, 128, 128, 0, 0, 0])
    mrkp = obj(order, b"mrkp", floats(order, 0.5, -0.25, 1) + ints(order, -2, 3)
               + uns(order, 3, 2, 12, 24, 5, 0, 0) + image)
    color = obj(order, b"cntr", obj(order, b"attr", b"") + obj(order, b"kdif", floats(order, 1, 1, 0)))
    return header(order) + obj(order, b"cntr", mrkp + color)


def main():
    for name, make in [("cameras", cameras_file), ("pixmap_marker", pixmap_marker_file)]:
        write_both(here, name, make)


if __name__ == "__main__":
    main()
