#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Writes the binary twins of textures.3dmf, laid out field by field as the
# 3D Metafile Reference describes TextureShader, ShaderData,
# ShaderUVTransform, PixmapTexture and MipmapTexture, big-endian as Mac
# QuickDraw 3D wrote them, and little-endian. The images are the same bytes
# in both (a texture's byte order is its own field, not the file's).
# Run from anywhere: python3 tests/data/make_texture_binary.py
import os

from mf3d import floats, header, obj, uns, write_both

here = os.path.dirname(os.path.abspath(__file__))

PIXMAP_IMAGE = bytes.fromhex("FFFF0000FF00FF0000000000FF0000FFFFFFFFFF00000000")
MIPMAP_IMAGE = bytes.fromhex("AAAAAAAA00001F00E003007CFF7F00001F00E003007C1F00E003")


def padded(data):
    return data + bytes((4 - len(data) % 4) % 4)


def textures_file(order):
    # Enumerations as their values: ARGB32 1, RGB16 2, BigEndian 0,
    # LittleEndian 1, Wrap 0, Clamp 1, True 1.
    first = obj(order, b"cntr", obj(order, b"txsu", b"")
                + obj(order, b"shdr", uns(order, 1, 0))
                + obj(order, b"sduv", floats(order, 2, 0, 0, 0, 1, 0, 0.25, 0, 1))
                + obj(order, b"txpm", uns(order, 2, 2, 12, 32, 1, 0, 0) + padded(PIXMAP_IMAGE)))
    second = obj(order, b"cntr", obj(order, b"txsu", b"")
                 + obj(order, b"txmm", uns(order, 1, 2, 0, 1, 4, 2, 8, 4) + padded(MIPMAP_IMAGE)))
    return header(order) + first + second


def main():
    write_both(here, "textures", textures_file)


if __name__ == "__main__":
    main()
