/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* q3compare: compares a rendered image with its golden image.
 *
 *   q3compare ACTUAL.png GOLDEN.png [--tolerance N] [--max-pixels M]
 *             [--diff DIFF.png] [--help]
 *
 * A pixel differs when one of its R, G, B, A channels differs from the
 * golden's by more than N (0 to 255, default 0); the images match when at
 * most M pixels differ (default 0). Both defaults are strict: one changed
 * bit fails. Exit status: 0 match, 1 mismatch (a one-line summary on
 * standard output: how many pixels differ, the largest difference and
 * where), 2 error (bad arguments, a file that cannot be read or written,
 * images of different sizes; a message on standard error). PNG files are
 * read and written through Q3's own extension, Q3PixmapPNG.h. */

#include "QD3D.h"
#include "QD3DErrors.h"
#include "Q3PixmapPNG.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kExitMatch = 0, kExitMismatch = 1, kExitError = 2 };

static void printUsage(FILE *to)
{
    fprintf(to, "usage: q3compare ACTUAL.png GOLDEN.png [--tolerance N] [--max-pixels M]\n"
                "                 [--diff DIFF.png]\n"
                "\n"
                "Compares a rendered image with its golden image, pixel by pixel.\n"
                "\n"
                "  --tolerance N    a pixel differs when one of its R, G, B, A channels differs\n"
                "                   by more than N, 0 to 255 (default 0: any change)\n"
                "  --max-pixels M   the images match when at most M pixels differ (default 0)\n"
                "  --diff DIFF.png  write the golden dimmed, pixels that differ beyond the\n"
                "                   tolerance in red and those that differ within it in yellow\n"
                "  --help, -h       print this text and exit\n"
                "\n"
                "Exit status: 0 match, 1 mismatch (a one-line summary on standard output:\n"
                "how many pixels differ, the largest difference and where), 2 error (bad\n"
                "arguments, a file that cannot be read or written, different sizes).\n");
}

static int usage(const char *why)
{
    fprintf(stderr, "q3compare: %s\n", why);
    printUsage(stderr);
    return kExitError;
}

/* A whole decimal number from 0 to max into *value; 0 if text is not one. */
static int parseCount(const char *text, unsigned long max, unsigned long *value)
{
    char *end;
    unsigned long parsed;
    if (text == NULL || text[0] < '0' || text[0] > '9')
        return 0;
    errno = 0;
    parsed = strtoul(text, &end, 10);
    if (errno != 0 || *end != '\0' || parsed > max)
        return 0;
    *value = parsed;
    return 1;
}

static int readImage(const char *path, TQ3Pixmap *image)
{
    if (Q3Pixmap_ReadPNG(path, kQ3PixelTypeARGB32, kQ3EndianBig, image) == kQ3Success)
        return 1;
    fprintf(stderr, "q3compare: %s\n", Q3Error_GetMessage());
    return 0;
}

/* What a comparison found. */
typedef struct {
    unsigned long differing;  /* pixels beyond the tolerance */
    unsigned long largest;    /* the largest channel difference of any pixel */
    unsigned long largestX, largestY;
    int largestChannel;       /* 0 A, 1 R, 2 G, 3 B (ARGB32 big-endian bytes) */
} Comparison;

/* Compares two ARGB32 big-endian pixmaps of the same size; when diff is not
 * NULL it receives the picture of the differences. */
static Comparison compare(const TQ3Pixmap *actual, const TQ3Pixmap *golden, unsigned long tolerance,
                          unsigned char *diff)
{
    Comparison result = {0, 0, 0, 0, 0};
    unsigned long x, y;
    int c;
    for (y = 0; y < golden->height; ++y)
        for (x = 0; x < golden->width; ++x) {
            const unsigned char *a = (const unsigned char *)actual->image + y * actual->rowBytes + 4 * x;
            const unsigned char *g = (const unsigned char *)golden->image + y * golden->rowBytes + 4 * x;
            unsigned long pixelLargest = 0;
            int pixelChannel = 0;
            for (c = 0; c < 4; ++c) {
                const unsigned long d = (unsigned long)(a[c] > g[c] ? a[c] - g[c] : g[c] - a[c]);
                if (d > pixelLargest) {
                    pixelLargest = d;
                    pixelChannel = c;
                }
            }
            if (pixelLargest > result.largest) {
                result.largest = pixelLargest;
                result.largestX = x;
                result.largestY = y;
                result.largestChannel = pixelChannel;
            }
            if (pixelLargest > tolerance)
                result.differing++;
            if (diff != NULL) {
                unsigned char *d = diff + (y * golden->width + x) * 4;
                d[0] = 255;
                if (pixelLargest > tolerance) {
                    d[1] = 255, d[2] = 0, d[3] = 0;
                } else if (pixelLargest > 0) {
                    d[1] = 255, d[2] = 255, d[3] = 0;
                } else {
                    /* The golden at a quarter of its contrast, over mid grey:
                     * recognisable, and never mistaken for a mark. */
                    d[1] = (unsigned char)(96 + g[1] / 4);
                    d[2] = (unsigned char)(96 + g[2] / 4);
                    d[3] = (unsigned char)(96 + g[3] / 4);
                }
            }
        }
    return result;
}

int main(int argc, char **argv)
{
    static const char *const kChannels[4] = {"A", "R", "G", "B"};
    const char *actualPath = NULL, *goldenPath = NULL, *diffPath = NULL;
    unsigned long tolerance = 0, maxPixels = 0;
    TQ3Pixmap actual, golden, diff;
    unsigned char *diffImage = NULL;
    Comparison result;
    int status = kExitError;
    int arg;

    for (arg = 1; arg < argc; ++arg) {
        if (strcmp(argv[arg], "--help") == 0 || strcmp(argv[arg], "-h") == 0) {
            printUsage(stdout);
            return kExitMatch;
        } else if (strcmp(argv[arg], "--tolerance") == 0) {
            if (!parseCount(arg + 1 < argc ? argv[++arg] : NULL, 255, &tolerance))
                return usage("--tolerance needs a whole number from 0 to 255");
        } else if (strcmp(argv[arg], "--max-pixels") == 0) {
            if (!parseCount(arg + 1 < argc ? argv[++arg] : NULL, (unsigned long)-1, &maxPixels))
                return usage("--max-pixels needs a whole number from 0");
        } else if (strcmp(argv[arg], "--diff") == 0) {
            if (arg + 1 >= argc)
                return usage("--diff needs a file name");
            diffPath = argv[++arg];
        } else if (argv[arg][0] == '-' && argv[arg][1] != '\0') {
            fprintf(stderr, "q3compare: unknown option %s\n", argv[arg]);
            return usage("see the options above");
        } else if (actualPath == NULL) {
            actualPath = argv[arg];
        } else if (goldenPath == NULL) {
            goldenPath = argv[arg];
        } else {
            return usage("too many file names");
        }
    }
    if (actualPath == NULL || goldenPath == NULL)
        return usage("two PNG files are needed, ACTUAL and GOLDEN");

    if (Q3Initialize() != kQ3Success) {
        fprintf(stderr, "q3compare: Q3Initialize failed\n");
        return kExitError;
    }
    memset(&actual, 0, sizeof actual);
    memset(&golden, 0, sizeof golden);
    if (!readImage(actualPath, &actual) || !readImage(goldenPath, &golden))
        goto done;
    if (actual.width != golden.width || actual.height != golden.height) {
        fprintf(stderr, "q3compare: the images have different sizes: %s is %lu x %lu, %s is %lu x %lu\n",
                actualPath, actual.width, actual.height, goldenPath, golden.width, golden.height);
        goto done;
    }
    if (diffPath != NULL) {
        diffImage = (unsigned char *)malloc(golden.width * golden.height * 4);
        if (diffImage == NULL) {
            fprintf(stderr, "q3compare: out of memory for the diff image\n");
            goto done;
        }
    }
    result = compare(&actual, &golden, tolerance, diffImage);
    if (diffImage != NULL) {
        diff = golden;
        diff.image = diffImage;
        if (Q3Pixmap_WritePNG(&diff, diffPath) != kQ3Success) {
            fprintf(stderr, "q3compare: %s\n", Q3Error_GetMessage());
            goto done;
        }
    }
    if (result.differing <= maxPixels) {
        status = kExitMatch;
    } else {
        printf("q3compare: %s differs from %s: %lu of %lu pixels differ by more than %lu (%lu allowed); "
               "largest difference %lu in %s at (%lu, %lu)\n",
               actualPath, goldenPath, result.differing, golden.width * golden.height, tolerance, maxPixels,
               result.largest, kChannels[result.largestChannel], result.largestX, result.largestY);
        status = kExitMismatch;
    }

done:
    free(diffImage);
    if (actual.image != NULL)
        Q3Pixmap_EmptyData(&actual);
    if (golden.image != NULL)
        Q3Pixmap_EmptyData(&golden);
    Q3Exit();
    return status;
}
