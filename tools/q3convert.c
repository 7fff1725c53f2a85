/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* q3convert: rewrites a 3DMF file, text or binary, or converts between
 * 3DMF and glTF 2.0, OBJ or STL (Q3Exchange.h).
 *
 *   q3convert in.3dmf out.3dmf [--text | --binary | --little-endian]
 *             [--normal | --stream | --database] [--help]
 *   q3convert in.3dmf out.glb|out.gltf|out.obj|out.stl [--subdivision VALUE]
 *             [--format FORMAT]
 *   q3convert in.glb|in.gltf|in.obj|in.stl out.3dmf [--text | ...]
 *
 * The format of each file comes from its extension (.glb, .gltf, .obj,
 * .stl; anything else is 3DMF), or --format for the output.
 * Every object is read and written back (unknown objects unchanged). The
 * default is a binary Normal file, big-endian as Mac QuickDraw 3D wrote them;
 * --little-endian writes a binary file in little-endian byte order
 * (kQ3FileModeSwap), where unknown objects of a big-endian input are left
 * out, since their data cannot be swapped. So are unknown objects of the
 * other encoding (an unknown text object has no binary form, an unknown
 * binary object no text form). Every warning the library posts while reading
 * or writing, these included, is printed to stderr. Exit
 * status: 0 done, 1 bad arguments, 2 the input cannot be read, 3 the output
 * cannot be written. */

#include "q3load.h"

#include "Q3Exchange.h"
#include "QD3DGroup.h"
#include "QD3DView.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

static void printUsage(FILE *to)
{
    fprintf(to, "usage: q3convert in.3dmf out.3dmf [--text | --binary | --little-endian]\n"
                "                 [--normal | --stream | --database]\n"
                "       q3convert in.3dmf out.glb|out.gltf|out.obj|out.stl [--subdivision VALUE]\n"
                "                 [--format FORMAT]\n"
                "       q3convert in.glb|in.gltf|in.obj|in.stl out.3dmf [--text | ...]\n"
                "\n"
                "Reads every object of in.3dmf and writes them to out.3dmf (unknown objects\n"
                "unchanged), or converts between 3DMF and glTF 2.0, OBJ (with its MTL file\n"
                "and PNG textures beside it) or STL: every geometry as triangles, line\n"
                "strips and points; groups as nodes; materials, textures, cameras and\n"
                "lights as far as each format carries them (docs/exchange.md). Formats\n"
                "come from the file extensions (.glb, .gltf, .obj, .stl; anything else is\n"
                "3DMF).\n"
                "\n"
                "  --format FORMAT  the output's format whatever its extension: 3dmf, glb,\n"
                "                   gltf, obj or stl\n"
                "  --subdivision VALUE  for glTF, OBJ and STL output: VALUE world units the longest side\n"
                "                   of a subdivided surface or curve (\"0.05\"), or VALUE\n"
                "                   segments around each one when it ends in 'x' (\"16x\");\n"
                "                   default 1/32 of the model's bounding box diagonal\n"
                "\n"
                "  --text           a text file\n"
                "  --binary         a big-endian binary file, as Mac QuickDraw 3D wrote them\n"
                "                   (default)\n"
                "  --little-endian  a little-endian binary file (kQ3FileModeSwap); unknown\n"
                "                   objects of a big-endian input are left out\n"
                "  --normal         a Normal file: objects written twice are written once and\n"
                "                   referred to (default)\n"
                "  --stream         a Stream file: every object written in full\n"
                "  --database       a Database file: every shared object listed in the table\n"
                "                   of contents, so that another file can refer to it\n"
                "  --help, -h       print this text and exit\n"
                "\n"
                "Unknown objects keep the encoding they were read in: a text output leaves\n"
                "out unknown binary objects, a binary output unknown text objects. Each object\n"
                "left out is named in a warning on standard error.\n"
                "\n"
                "Exit status: 0 done, 1 bad arguments, 2 the input cannot be read, 3 the\n"
                "output cannot be written.\n");
}

static int usage(void)
{
    printUsage(stderr);
    return 1;
}

/* The format a path's extension names: 0 for 3DMF. */
static TQ3ExchangeFormat formatOfPath(const char *path)
{
    const char *dot = strrchr(path, '.');
    char ext[8];
    size_t i;
    if (dot == NULL || strchr(dot, '/') != NULL || strlen(dot + 1) >= sizeof ext)
        return kQ3ExchangeFormatAny;
    for (i = 0; dot[1 + i] != '\0'; ++i)
        ext[i] = (char)tolower((unsigned char)dot[1 + i]);
    ext[i] = '\0';
    if (strcmp(ext, "glb") == 0)
        return kQ3ExchangeFormatGLB;
    if (strcmp(ext, "gltf") == 0)
        return kQ3ExchangeFormatGLTF;
    if (strcmp(ext, "obj") == 0)
        return kQ3ExchangeFormatOBJ;
    if (strcmp(ext, "stl") == 0)
        return kQ3ExchangeFormatSTL;
    return kQ3ExchangeFormatAny;
}

/* --format's word: 1 and *format set, or 0 for a word it does not know. */
static int formatOfName(const char *name, TQ3ExchangeFormat *format)
{
    if (strcmp(name, "3dmf") == 0)
        *format = kQ3ExchangeFormatAny;
    else if (strcmp(name, "glb") == 0)
        *format = kQ3ExchangeFormatGLB;
    else if (strcmp(name, "gltf") == 0)
        *format = kQ3ExchangeFormatGLTF;
    else if (strcmp(name, "obj") == 0)
        *format = kQ3ExchangeFormatOBJ;
    else if (strcmp(name, "stl") == 0)
        *format = kQ3ExchangeFormatSTL;
    else
        return 0;
    return 1;
}

/* --subdivision's value: "0.05" world units, "16x" segments. */
static int parseSubdivision(const char *text, TQ3ExchangeOptions *options)
{
    char *end = NULL;
    double value = strtod(text, &end);
    if (end == text || !(value > 0.0) || value > 1e30)
        return 0;
    options->subdivisionFromSize = kQ3False;
    options->subdivisionMethod = kQ3SubdivisionMethodWorldSpace;
    if (*end == 'x') {
        options->subdivisionMethod = kQ3SubdivisionMethodConstant;
        ++end;
    }
    options->subdivisionValue = (float)value;
    return *end == '\0';
}

/* Writes every object read from a 3DMF file, in one group, as glTF. */
static int writeGltf(TQ3Object *objects, long count, const char *out, TQ3ExchangeOptions *options)
{
    TQ3GroupObject group = Q3Group_New();
    int status = 0;
    long i;
    for (i = 0; i < count; ++i)
        Q3Group_AddObject(group, objects[i]);
    if (Q3Exchange_Write(group, out, options) != kQ3Success) {
        fprintf(stderr, "cannot write %s: %s\n", out, Q3Error_GetMessage());
        status = 3;
    }
    Q3Object_Dispose(group);
    return status;
}

int main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    TQ3FileMode encoding = 0, mode = kQ3FileModeNormal;
    TQ3Object *objects = NULL;
    long count, i;
    int status = 0;
    int arg;
    int formatGiven = 0;
    TQ3ExchangeFormat outFormat = kQ3ExchangeFormatAny;
    TQ3ExchangeOptions options;
    options.format = kQ3ExchangeFormatAny;
    options.subdivisionFromSize = kQ3True;
    options.subdivisionMethod = kQ3SubdivisionMethodWorldSpace;
    options.subdivisionValue = 1.0f;
    options.view = NULL;
    for (arg = 1; arg < argc; ++arg) {
        if (strcmp(argv[arg], "--format") == 0) {
            if (++arg == argc || !formatOfName(argv[arg], &outFormat))
                return usage();
            formatGiven = 1;
        } else if (strcmp(argv[arg], "--subdivision") == 0) {
            if (++arg == argc || !parseSubdivision(argv[arg], &options))
                return usage();
        } else if (strcmp(argv[arg], "--text") == 0)
            encoding = kQ3FileModeText;
        else if (strcmp(argv[arg], "--binary") == 0)
            encoding = 0;
        else if (strcmp(argv[arg], "--little-endian") == 0)
            encoding = kQ3FileModeSwap;
        else if (strcmp(argv[arg], "--normal") == 0)
            mode = kQ3FileModeNormal;
        else if (strcmp(argv[arg], "--stream") == 0)
            mode = kQ3FileModeStream;
        else if (strcmp(argv[arg], "--database") == 0)
            mode = kQ3FileModeDatabase;
        else if (strcmp(argv[arg], "--help") == 0 || strcmp(argv[arg], "-h") == 0) {
            printUsage(stdout);
            return 0;
        } else if (argv[arg][0] == '-')
            return usage();
        else if (in == NULL)
            in = argv[arg];
        else if (out == NULL)
            out = argv[arg];
        else
            return usage();
    }
    if (in == NULL || out == NULL)
        return usage();
    if (!formatGiven)
        outFormat = formatOfPath(out);
    if (Q3Initialize() != kQ3Success)
        return 3;
    Q3Warning_Register(q3load_printWarning, 0);
    if (formatOfPath(in) != kQ3ExchangeFormatAny) {
        /* glTF in: one display group. */
        TQ3GroupObject group = Q3Exchange_Read(in, kQ3ExchangeFormatAny);
        if (group == NULL) {
            fprintf(stderr, "%s cannot be read: %s\n", in, Q3Error_GetMessage());
            Q3Exit();
            return 2;
        }
        objects = (TQ3Object *)malloc(sizeof(TQ3Object));
        if (objects == NULL) {
            Q3Object_Dispose(group);
            Q3Exit();
            return 3;
        }
        objects[0] = group;
        count = 1;
    } else {
        count = q3load_read(in, &objects);
        if (count < 0) {
            Q3Exit();
            return 2;
        }
    }
    if (outFormat != kQ3ExchangeFormatAny) {
        options.format = outFormat;
        status = writeGltf(objects, count, out, &options);
        q3load_free(objects, count);
        Q3Exit();
        return status;
    }
    {
        TQ3StorageObject storage = Q3UnixPathStorage_New(out);
        TQ3FileObject file = Q3File_New();
        TQ3ViewObject view = Q3View_New();
        TQ3ViewStatus done = kQ3ViewStatusError;
        if (Q3File_SetStorage(file, storage) == kQ3Success && Q3File_OpenWrite(file, mode | encoding) == kQ3Success &&
            Q3View_StartWriting(view, file) == kQ3Success) {
            do {
                for (i = 0; i < count; ++i)
                    Q3Object_Submit(objects[i], view);
                done = Q3View_EndWriting(view);
            } while (done == kQ3ViewStatusRetraverse);
            if (Q3File_Close(file) != kQ3Success)
                done = kQ3ViewStatusError;
        }
        if (done != kQ3ViewStatusDone) {
            fprintf(stderr, "cannot write %s: %s\n", out, Q3Error_GetMessage());
            status = 3;
        }
        Q3Object_Dispose(view);
        Q3Object_Dispose(file);
        Q3Object_Dispose(storage);
    }
    q3load_free(objects, count);
    Q3Exit();
    return status;
}
