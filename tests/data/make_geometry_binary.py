#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Writes the binary twins of the hand-written geometry test files of
# tests/data (nurbpatch.3dmf ...), laid out field by field as the 3D Metafile
# Reference describes them: big-endian as Mac QuickDraw 3D wrote them, and
# little-endian. Run from anywhere: python3 tests/data/make_geometry_binary.py
import os

from mf3d import color_set, floats, header, ints, obj, uns, write_both

here = os.path.dirname(os.path.abspath(__file__))


def curve2d(order, k, points, knots):
    flat = [c for p in points for c in p]
    return obj(order, b"nb2c", uns(order, k, len(points)) + floats(order, *flat) + floats(order, *knots))


def nurbpatch_file(order):
    # The patch of nurbpatch.3dmf: 3 rows of 4 points, a kept square and a
    # triangular hole.
    points = [-1.5, -1, 0, 1, -0.5, -1, 0.5, 1, 0.5, -1, 0.5, 1, 1.5, -1, 0, 1,
              -1.5, 0, 0.5, 1, -1, 0, 2, 2, 0.5, 0, 1, 1, 1.5, 0, 0.5, 1,
              -1.5, 1, 0, 1, -0.5, 1, 0.5, 1, 0.5, 1, 0.5, 1, 1.5, 1, 0, 1]
    patch = obj(order, b"nrbp", uns(order, 3, 3, 3, 4) + floats(order, *points)
                + floats(order, 0, 0, 0, 0.5, 1, 1, 1) + floats(order, 0, 0, 0, 1, 1, 1))
    outer = obj(order, b"cntr", obj(order, b"trml", b"")
                + curve2d(order, 2, [(0.1, 0.1, 1), (0.9, 0.1, 1), (0.9, 0.9, 1), (0.1, 0.9, 1), (0.1, 0.1, 1)],
                          [0, 0, 1, 2, 3, 4, 4]))
    hole = obj(order, b"cntr", obj(order, b"trml", b"")
               + curve2d(order, 2, [(0.4, 0.4, 1), (0.4, 0.6, 1), (0.6, 0.6, 1)], [0, 0, 1, 2, 2])
               + curve2d(order, 3, [(0.6, 0.6, 1), (1.2, 0.8, 2), (0.4, 0.4, 1)], [0, 0, 0, 1, 1, 1]))
    return header(order) + obj(order, b"cntr", patch + outer + hole + color_set(order, 0.2, 0.6, 0.9))


def set_list(order, tag, count, packing, indices, sets):
    return obj(order, b"cntr", obj(order, tag, uns(order, count, packing, len(indices), *indices)) + b"".join(sets))


def mesh_file(order):
    # The mesh of mesh.3dmf: a square with a square hole, a triangle beside
    # it, a corner, a face, a vertex and the mesh's own set.
    points = [-2, -1, 0, 0, -1, 0, 0, 1, 0, -2, 1, 0, -1.5, -0.5, 0, -0.5, -0.5, 0, -0.5, 0.5, 0, -1.5, 0.5, 0,
              1.5, 0, 0.5]
    mesh = obj(order, b"mesh", uns(order, 9) + floats(order, *points) + uns(order, 2, 1)
               + ints(order, 4, 0, 1, 2, 3) + ints(order, -4, 4, 7, 6, 5) + ints(order, 3, 1, 8, 2))
    corners = obj(order, b"cntr", obj(order, b"crnr", uns(order, 1, 1, 2, 2, 0)) + color_set(order, 0, 0, 1))
    faces = set_list(order, b"fasl", 3, 0, [2], [color_set(order, 0, 1, 0)])
    vertices = set_list(order, b"vasl", 9, 0, [2], [color_set(order, 1, 0, 0)])
    return header(order) + obj(order, b"cntr", mesh + corners + faces + vertices + color_set(order, 0.8, 0.8, 0.2))


def polygons_file(order):
    # The objects of polygons.3dmf: a general polygon, a triangle grid, a
    # polyhedron and a marker (its 10 bytes of image padded to 12).
    red = color_set(order, 1, 0, 0)
    gpgn = obj(order, b"gpgn", uns(order, 2, 4) + floats(order, -2, -1.5, 0, 2, -1.5, 0, 2, 1.5, 0, -2, 1.5, 0)
               + uns(order, 3) + floats(order, -0.5, -0.5, 0, 0, 0.75, 0, 0.5, -0.5, 0))
    general = obj(order, b"cntr", gpgn + obj(order, b"gplh", uns(order, 1))
                  + set_list(order, b"vasl", 7, 0, [0, 5], [red, red]) + color_set(order, 0.3, 0.5, 1))
    trig = obj(order, b"trig", uns(order, 2, 3) + floats(order, -2, -1, 0, 0, -1, 0.5, 2, -1, 0, -2, 1, 0, 0, 1, 0.5,
                                                         2, 1, 0))
    grid = obj(order, b"cntr", trig + set_list(order, b"fasl", 4, 0, [1], [color_set(order, 0, 1, 0)])
               + set_list(order, b"vasl", 6, 1, [0, 2, 3, 4, 5], [red]) + color_set(order, 0.9, 0.9, 0.9))
    plhd = obj(order, b"plhd", uns(order, 4) + floats(order, -1.5, -1, -1, 1.5, -1, -1, 0, -1, 1.5, 0, 1.5, 0)
               + uns(order, 4, 2, 0, 2, 1, 7, 0, 1, 3, 3, 1, 2, 3, 7, 2, 0, 3, 4, 0, 1, 0, 1, 1, 3, 1, 2))
    poly = obj(order, b"cntr", plhd + set_list(order, b"fasl", 4, 0, [1], [color_set(order, 0, 0, 1)])
               + set_list(order, b"vasl", 4, 0, [1], [red])
               + set_list(order, b"gasl", 2, 0, [1], [color_set(order, 0, 1, 1)]))
    mrkr = obj(order, b"mrkr", floats(order, 0.5, -0.25, 0) + ints(order, -3, 2) + uns(order, 10, 5, 2, 1)
               + bytes([1, 0, 3, 0, 255, 3, 3, 0, 1, 0, 0, 0]))
    marker = obj(order, b"cntr", mrkr + color_set(order, 1, 1, 0))
    return header(order) + general + grid + poly + marker


def cap_set(order, tag, r, g, b):
    return obj(order, b"cntr", obj(order, tag, b"") + color_set(order, r, g, b))


def part_sets_file(order):
    # The objects of part_sets.3dmf: a box with face sets, a cylinder with
    # cap, face and interior sets, a polyline with segment sets.
    box = obj(order, b"cntr", obj(order, b"box ", floats(order, 0, 2, 0, 2, 0, 0, 0, 0, 1.5, -1, -1, -1))
              + set_list(order, b"fasl", 6, 1, [1, 3, 4], [color_set(order, 1, 0, 0), color_set(order, 0, 1, 0),
                                                           color_set(order, 0, 0, 1)]))
    cylinder = obj(order, b"cntr",
                   obj(order, b"cyln", floats(order, 0, 2, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 0.75, 0, 1))
                   + obj(order, b"caps", uns(order, 7))
                   + cap_set(order, b"icas", 1, 1, 0) + cap_set(order, b"tcas", 1, 0, 0)
                   + cap_set(order, b"fcas", 0, 0, 1) + cap_set(order, b"bcas", 0, 1, 0))
    polyline = obj(order, b"cntr", obj(order, b"plyl", uns(order, 4) + floats(order, -2, -1, 0, -1, 1, 0, 1, -1, 0,
                                                                          2, 1, 0))
                   + set_list(order, b"gasl", 3, 0, [0, 2], [color_set(order, 1, 0, 0), color_set(order, 0, 0, 1)]))
    return header(order) + box + cylinder + polyline


def main():
    for name, make in [("nurbpatch", nurbpatch_file), ("mesh", mesh_file), ("polygons", polygons_file),
                       ("part_sets", part_sets_file)]:
        write_both(here, name, make)


if __name__ == "__main__":
    main()
