#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Writes the files laid out as Apple-era tools wrote 3DMF (issue 25):
#
#   apple_content_{be,le}.3dmf   binary, both byte orders: a display group
#       written as Apple's tools write it (BeginGroup holding the group and
#       its DisplayGroupState as siblings, no container), a plain group in
#       it, a TriMesh whose attribute set holds a texture shader and whose
#       triangles have a surface shader attribute array (a container: the
#       array, then one shader per triangle, the second a Reference to the
#       first set's shader through the table of contents), a Triangle whose
#       own set holds a shader, and 12 bytes of padding after the last
#       object.
#   apple_content_{lf,cr,crlf}.3dmf   the same objects in text, written with
#       each line end (Macs wrote CR), with True/False where a number is
#       stored, keywords and enumeration words in other cases, a state
#       object after the BeginGroup instead of inside it, and a blank line of
#       junk after the last object.
#   bad_group_{empty,nogroup}_be.3dmf, bad_shader_array_be.3dmf,
#   bad_text_comment_cr.3dmf   malformed variants: a BeginGroup holding
#       nothing, a BeginGroup holding a triangle, a surface shader array
#       holding more shaders than triangles, a CR-only file whose one line
#       holds an unclosed object.
#
# Run from anywhere: python3 tests/data/make_content_files.py
import os
import struct

from mf3d import floats, header, obj, uns

here = os.path.dirname(os.path.abspath(__file__))

# Two 2 x 1 RGB32 textures (rows of 8 bytes): red|green and blue|white.
RED_GREEN = bytes.fromhex("00FF000000 00FF00".replace(" ", ""))
BLUE_WHITE = bytes.fromhex("000000FF00FFFFFF")


def pixmap_shader(order, image):
    # TextureShader with a PixmapTexture: width 2, height 1, rowBytes 8,
    # pixelSize 32, RGB32 (0), BigEndian bit and byte order (0 0).
    return obj(order, b"cntr", obj(order, b"txsu", b"") +
               obj(order, b"txpm", uns(order, 2, 1, 8, 32, 0, 0, 0) + image))


def trimesh(order, points, triangles, subobjects):
    # Counts: triangles, triangle attribute types, edges, edge attribute
    # types, points, vertex attribute types; 8-bit indices (fewer than 256
    # points), the points, the bounding box and isEmpty.
    data = uns(order, len(triangles), 1, 0, 0, len(points), 1)
    for t in triangles:
        data += bytes(t)
    for p in points:
        data += floats(order, *p)
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    zs = [p[2] for p in points]
    data += floats(order, min(xs), min(ys), min(zs), max(xs), max(ys), max(zs)) + uns(order, 0)
    return obj(order, b"cntr", obj(order, b"tmsh", data) + subobjects)


QUAD = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
QUAD_UV = [(0, 0), (1, 0), (1, 1), (0, 1)]


def content(order, junk=True):
    first_shader = pixmap_shader(order, RED_GREEN)
    # The TriMesh's own attribute set: white, and the first shader (whose
    # position the table of contents gives, for the Reference below).
    own_set = obj(order, b"cntr", obj(order, b"attr", b"") + obj(order, b"kdif", floats(order, 1, 1, 1)))
    own_prefix = obj(order, b"cntr", b"")  # placeholder to compute offsets
    # Surface shader array over the 2 triangles: attribute type 11, 0,
    # triangles (0), index 0, no use flags; then the two shaders, the
    # second a Reference (ID 1) to the attribute set's shader.
    shader_array = obj(order, b"cntr", obj(order, b"atar", ints(order, 11) + uns(order, 0, 0, 0, 0)) +
                       pixmap_shader(order, BLUE_WHITE) + obj(order, b"rfrn", uns(order, 1)))
    uv_array = obj(order, b"atar", ints(order, 1) + uns(order, 0, 2, 0, 0) +
                   floats(order, *[c for uv in QUAD_UV for c in uv]))
    mesh_head = trimesh(order, QUAD, [(0, 1, 2), (0, 2, 3)], b"")
    # Lay the TriMesh container out by hand to know where the set's shader
    # starts: cntr( tmsh, shader array, uv array, cntr( attr, kdif, shader ) ).
    tmsh_obj = mesh_head[8:]  # the tmsh object inside the container built above
    set_body_before_shader = obj(order, b"attr", b"") + obj(order, b"kdif", floats(order, 1, 1, 1))
    set_obj = obj(order, b"cntr", set_body_before_shader + first_shader)
    mesh = obj(order, b"cntr", tmsh_obj + shader_array + uv_array + set_obj)
    # The Triangle: its own set holds a reference to the same shader too.
    triangle = obj(order, b"cntr", obj(order, b"trng", floats(order, -1, -1, 1, 1, -1, 1, 0, 1, 1)) +
                   obj(order, b"cntr", obj(order, b"attr", b"") + obj(order, b"rfrn", uns(order, 1))))
    plain = obj(order, b"bgng", obj(order, b"grop", b""))
    inner = plain + triangle + obj(order, b"endg", b"")
    # Display group: BeginGroup ( DisplayGroup, DisplayGroupState ( Inline ) ).
    outer_begin = obj(order, b"bgng", obj(order, b"dspg", b"") + obj(order, b"dgst", uns(order, 1)))
    body = outer_begin + mesh + inner + obj(order, b"endg", b"")
    # Where the set's shader starts in the file: header (24), then within body.
    shader_at = 24 + len(outer_begin) + 8 + len(tmsh_obj) + len(shader_array) + len(uv_array) + 8 + \
        len(set_body_before_shader)
    toc_at = 24 + len(body)
    # Table of contents: next toc 0 (u64), reference seed 2, type seed 0,
    # entry type 1, entry size 16, 1 entry: ID 1, its offset (u64), its type.
    toc = obj(order, b"toc ", struct.pack(order + "Q", 0) + uns(order, 2) + ints(order, 0) + uns(order, 1, 16, 1, 1) +
              struct.pack(order + "Q", shader_at) + (b"cntr" if order == ">" else b"rtnc"))
    out = header(order, toc=toc_at) + body + toc
    if junk:
        out += bytes(12)
    return out


def ints(order, *values):
    return struct.pack(order + "%di" % len(values), *values)


TEXT = """# A model as Apple's tools wrote them: a display group whose state follows
# its BeginGroup, a textured TriMesh, booleans as words, keywords in any case.
3DMetafile ( 1 6 Normal toc> )
BeginGroup ( DisplayGroup ( ) )
DisplayGroupState ( Inline )
container (
  TRIMESH (
    2 1 0 0 4 1
    0 1 2  0 2 3
    -1 -1 0  1 -1 0  1 1 0  -1 1 0
    -1 -1 0  1 1 0
    False            # isEmpty, as a word
  )
  Container (
    AttributeArray ( 11 0 0 0 0 )
    Container (
      TextureShader ( )
      PixmapTexture ( 2 1 8 32 rgb32 BIGENDIAN BigEndian 0x000000FF00FFFFFF )
    )
    Reference ( 1 )
  )
  attributearray ( 1 0 2 0 FALSE  0 0  1 0  1 1  0 1 )
  Container (
    AttributeSet ( )
    DiffuseColor ( 1 1 1 )
    shader1: Container (
      textureshader ( )
      PixmapTexture ( 2 1 8 32 RGB32 BigEndian bigendian 0x00FF00000000FF00 )
    )
  )
)
BeginGroup ( Group ( ) )
Container (
  Triangle ( -1 -1 1  1 -1 1  0 1 1 )
  Container ( AttributeSet ( ) Reference ( 1 ) )
)
EndGroup ( )
endgroup ( )
toc: TableOfContents ( 0 2 0 1 16 1
  1 shader1>
  Container
)
"""


def main():
    for suffix, order in [("_be", ">"), ("_le", "<")]:
        with open(os.path.join(here, "apple_content" + suffix + ".3dmf"), "wb") as out:
            out.write(content(order))
    text = TEXT.replace("\n", "\r\n")
    junk = "\r\n\x00\x00"
    for suffix, end in [("_lf", "\n"), ("_cr", "\r"), ("_crlf", "\r\n")]:
        with open(os.path.join(here, "apple_content" + suffix + ".3dmf"), "wb") as out:
            out.write((TEXT.replace("\n", end) + junk).encode("ascii"))
    order = ">"
    bad = {
        "bad_group_empty_be": header(order) + obj(order, b"bgng", b"") + obj(order, b"endg", b""),
        "bad_group_nogroup_be": header(order) + obj(order, b"bgng", obj(order, b"trng", floats(order, *range(9)))) +
        obj(order, b"endg", b""),
        "bad_shader_array_be": header(order) + trimesh(order, QUAD, [(0, 1, 2), (0, 2, 3)], obj(
            order, b"cntr", obj(order, b"atar", ints(order, 11) + uns(order, 0, 0, 0, 0)) +
            pixmap_shader(order, RED_GREEN) + pixmap_shader(order, RED_GREEN) + pixmap_shader(order, RED_GREEN)) +
            obj(order, b"atar", ints(order, 1) + uns(order, 0, 2, 0, 0) + floats(order, *[0] * 8))),
    }
    for name, data in bad.items():
        with open(os.path.join(here, name + ".3dmf"), "wb") as out:
            out.write(data)
    with open(os.path.join(here, "bad_text_comment_cr.3dmf"), "wb") as out:
        out.write(b"3DMetafile ( 1 6 Normal )\r# a comment\rTriangle ( 0 0 0  1 0 0  0 1 0\r")


if __name__ == "__main__":
    main()
