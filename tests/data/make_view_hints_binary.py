#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Writes the binary twins of view_hints.3dmf, laid out field by field as the
# 3D Metafile Reference describes a ViewHints container and its children
# (cameras and lights as in make_camera_binary.py and Apple's MF3D parser),
# big-endian as Mac QuickDraw 3D wrote them, and little-endian.
# Run from anywhere: python3 tests/data/make_view_hints_binary.py
import os

from mf3d import floats, header, obj, uns, write_both

here = os.path.dirname(os.path.abspath(__file__))


def light_data(order, on, brightness, r, g, b):
    return obj(order, b"lght", uns(order, on) + floats(order, brightness, r, g, b))


def view_hints_file(order):
    camera = obj(order, b"cntr", obj(order, b"vana", floats(order, 0.6, 1.25))
                 + obj(order, b"cmpl", floats(order, 0, 1, 6, 0, 0, 0, 0, 1, 0))
                 + obj(order, b"cmrg", floats(order, 0.5, 40))
                 + obj(order, b"cmvp", floats(order, -1, 1, 2, 2)))
    ambient = obj(order, b"cntr", obj(order, b"ambn", b"") + light_data(order, 1, 0.25, 1, 1, 1))
    directional = obj(order, b"cntr", obj(order, b"drct", floats(order, 0, 0, -1) + uns(order, 0))
                      + light_data(order, 1, 0.75, 1, 0.5, 0.25))
    attributes = obj(order, b"cntr", obj(order, b"attr", b"") + obj(order, b"kdif", floats(order, 0.25, 0.5, 0.75)))
    # 12 x 2 bits, rows of 2 bytes: 4 bytes of image, already a multiple of 4.
    mask = obj(order, b"immk", uns(order, 12, 2, 2) + bytes([0xF0, 0x0F, 0xA5, 0xA0]))
    hints = obj(order, b"cntr", obj(order, b"vwhn", b"") + camera + ambient + directional + attributes
                + obj(order, b"imdm", uns(order, 320, 200)) + mask
                + obj(order, b"imcc", floats(order, 0.125, 0.375, 0.625)))
    return header(order) + hints + obj(order, b"vwhn", b"")


def main():
    write_both(here, "view_hints", view_hints_file)


if __name__ == "__main__":
    main()
