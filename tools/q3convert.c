/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* q3convert: rewrites a 3DMF file, text or binary.
 *
 *   q3convert in.3dmf out.3dmf [--text | --binary | --little-endian]
 *             [--normal | --stream | --database] [--help]
 *
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

#include "QD3DView.h"

#include <string.h>

static void printUsage(FILE *to)
{
    fprintf(to, "usage: q3convert in.3dmf out.3dmf [--text | --binary | --little-endian]\n"
                "                 [--normal | --stream | --database]\n"
                "\n"
                "Reads every object of in.3dmf and writes them to out.3dmf (unknown objects\n"
                "unchanged).\n"
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

int main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    TQ3FileMode encoding = 0, mode = kQ3FileModeNormal;
    TQ3Object *objects = NULL;
    long count, i;
    int status = 0;
    int arg;
    for (arg = 1; arg < argc; ++arg) {
        if (strcmp(argv[arg], "--text") == 0)
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
    if (Q3Initialize() != kQ3Success)
        return 3;
    Q3Warning_Register(q3load_printWarning, 0);
    count = q3load_read(in, &objects);
    if (count < 0) {
        Q3Exit();
        return 2;
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
