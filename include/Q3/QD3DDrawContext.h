/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Draw contexts: where a view's renderer puts its image. Q3 provides the
 * pixmap draw context, which renders into memory the caller owns.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged. "Not a live Q3 object" means a handle that was disposed
 * or never came from Q3. The checks run in this order, and the first that
 * fails decides the error: Q3 is initialized; then the arguments from left
 * to right (a handle: not NULL, a live Q3 object, of the right class; a
 * pointer: not NULL); then the function's other conditions in the order it
 * lists them (for a data structure, the rules given with its type, in their
 * order).
 *
 * Changes made to a draw context while a view is rendering into it take
 * effect at that view's next Q3View_StartRendering.
 *
 * TQ3Boolean fields and arguments: any value other than kQ3False is taken,
 * and stored, as kQ3True (legacy code often leaves them as plain nonzero
 * ints).
 */
#ifndef QD3DDRAWCONTEXT_H
#define QD3DDRAWCONTEXT_H

#include "QD3D.h"

/* As in Apple's header: the X11 draw context's types come from Xlib. */
#if defined(WINDOW_SYSTEM_X11) && WINDOW_SYSTEM_X11
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* What Q3View_StartRendering does to the image before drawing. */
enum TQ3DrawContextClearImageMethod {
    kQ3ClearMethodNone      = 0, /* leave the pixels as they are          */
    kQ3ClearMethodWithColor = 1  /* fill the pane (or image) with
                                    clearImageColor                       */
};
typedef enum TQ3DrawContextClearImageMethod TQ3DrawContextClearImageMethod;

/*
 * State common to every draw context.
 *   clearImageMethod   see TQ3DrawContextClearImageMethod.
 *   clearImageColor    the clear colour; components outside 0 to 1 are
 *                      clamped when used.
 *   pane               the rectangle drawn into, in pixels: (0, 0) is the
 *                      top-left corner of the top-left pixel, x grows to the
 *                      right and y downwards. The camera's view port is
 *                      mapped onto the pane; pixels of the pane outside the
 *                      image are not drawn.
 *   paneState          kQ3True to draw into pane only; kQ3False to draw into
 *                      the whole image (pane is then ignored and may hold
 *                      anything).
 *   mask, maskState    with maskState kQ3True, Q3View_EndRendering writes
 *                      only the pixmap pixels whose bit is set in mask:
 *                      pixel (x, y) of the pixmap is bit x of row y of the
 *                      mask (rows rowBytes apart, top row first; bitOrder
 *                      kQ3EndianBig: the most significant bit of a byte is
 *                      its leftmost pixel). Pixels outside the mask's width
 *                      and height are not written; the other pixels keep
 *                      what they held. mask.image is read, never copied or
 *                      freed: it must stay valid while the state is on.
 *   doubleBufferState  stored and returned as given; a pixmap draw context is
 *                      always drawn into directly (Q3 renders offscreen and
 *                      writes the finished frame, as double buffering would).
 *
 * The rules a TQ3DrawContextData must obey wherever one is accepted
 * (Q3PixmapDrawContext_New, Q3DrawContext_SetData), all reported as
 * kQ3ErrorInvalidData:
 *   clearImageMethod is a TQ3DrawContextClearImageMethod value;
 *   the clearImageColor components are finite;
 *   when paneState is kQ3True: the pane coordinates are finite,
 *     pane.min.x < pane.max.x and pane.min.y < pane.max.y;
 *   when maskState is kQ3True: mask obeys the mask rules below.
 *
 * The mask rules (Q3DrawContext_SetMask, and SetData with the mask on):
 * mask.image is not NULL, width >= 1, height >= 1,
 * rowBytes >= (width + 7) / 8, and bitOrder is a TQ3Endian value.
 */
struct TQ3DrawContextData {
    TQ3DrawContextClearImageMethod clearImageMethod;
    TQ3ColorARGB clearImageColor;
    TQ3Area pane;
    TQ3Boolean paneState;
    TQ3Bitmap mask;
    TQ3Boolean maskState;
    TQ3Boolean doubleBufferState;
};
typedef struct TQ3DrawContextData TQ3DrawContextData;

/*
 * A pixmap draw context: the common state plus the image (TQ3Pixmap, in
 * QD3D.h) rendered into.
 *
 * How Q3 writes a pixel. Each pixel is a pixelSize-bit unsigned value whose
 * channels sit in the order the type's name gives, most significant first:
 *   kQ3PixelTypeARGB32     32 bits  A 31-24, R 23-16, G 15-8, B 7-0
 *   kQ3PixelTypeRGB32      32 bits  bits 31-24 unused, R 23-16, G 15-8, B 7-0
 *   kQ3PixelTypeARGB16     16 bits  A 15, R 14-10, G 9-5, B 4-0
 *   kQ3PixelTypeRGB16      16 bits  bit 15 unused, R 14-10, G 9-5, B 4-0
 *   kQ3PixelTypeRGB16_565  16 bits  R 15-11, G 10-5, B 4-0
 *   kQ3PixelTypeRGB24      24 bits  R 23-16, G 15-8, B 7-0
 * Channel values from 0 to 1 are scaled to the channel's range and rounded to
 * nearest; unused bits are written as ones. Alpha is 1 wherever geometry is
 * drawn and the clear colour's alpha wherever only the clear reaches.
 * byteOrder is the order in which the bytes of each pixel value are stored
 * (kQ3EndianBig: most significant byte at the lowest address). bitOrder is
 * not used for pixmaps. Rows are stored top row first, rowBytes apart.
 *
 * The rules a TQ3Pixmap must obey wherever one is accepted
 * (Q3PixmapDrawContext_New, Q3PixmapDrawContext_SetPixmap), with the error
 * posted when one is broken, checked in this order:
 *   image is not NULL                               kQ3ErrorNULLParameter
 *   pixelType is a TQ3PixelType value, and
 *     byteOrder and bitOrder are TQ3Endian values   kQ3ErrorInvalidData
 *   pixelSize is the size the table above gives
 *     for pixelType                          kQ3ErrorUnsupportedPixelDepth
 *   width >= 1, height >= 1, and
 *     rowBytes >= width * pixelSize / 8             kQ3ErrorInvalidData
 *
 * The image memory stays the caller's: Q3 neither copies nor frees it. It
 * must remain valid, and must not move, for as long as a view may render
 * into the draw context with this pixmap.
 */
struct TQ3PixmapDrawContextData {
    TQ3DrawContextData drawContextData;
    TQ3Pixmap pixmap;
};
typedef struct TQ3PixmapDrawContextData TQ3PixmapDrawContextData;

/* ---- Draw context ------------------------------------------------------- */

/**
 * Reports the kind of a draw context.
 *
 * @param drawContext  the draw context to query.
 * @return its type code (kQ3DrawContextTypePixmap for a pixmap draw
 *         context), or kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      drawContext is NULL.
 *   kQ3ErrorInvalidObject      drawContext is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  drawContext is not a draw context.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3DrawContext_GetType(TQ3DrawContextObject drawContext);

/**
 * Replaces all the common state of a draw context at once.
 *
 * @param context      the draw context to change.
 * @param contextData  the new state; it must obey the TQ3DrawContextData
 *                     rules above. It is copied.
 * @return kQ3Success, or kQ3Failure with the draw context unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or contextData is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *   kQ3ErrorInvalidData        contextData breaks a TQ3DrawContextData rule.
 *
 * Ownership: no references change; mask.image stays the caller's.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_SetData(TQ3DrawContextObject context,
                                                 const TQ3DrawContextData *contextData);

/**
 * Reads all the common state of a draw context.
 *
 * @param context      the draw context to read.
 * @param contextData  receives the state as last set.
 * @return kQ3Success, or kQ3Failure with *contextData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or contextData is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *
 * Ownership: no references change; mask.image is the pointer the caller gave.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_GetData(TQ3DrawContextObject context,
                                                 TQ3DrawContextData *contextData);

/**
 * Sets the colour Q3View_StartRendering clears the image to when the clear
 * method is kQ3ClearMethodWithColor.
 *
 * @param context  the draw context to change.
 * @param color    the clear colour; components must be finite and are
 *                 clamped to 0 to 1 when used.
 * @return kQ3Success, or kQ3Failure with the draw context unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or color is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *   kQ3ErrorInvalidParameter   a component of *color is not finite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_SetClearImageColor(TQ3DrawContextObject context,
                                                            const TQ3ColorARGB *color);

/**
 * Reads the clear colour of a draw context, as set (not clamped).
 *
 * @param context  the draw context to read.
 * @param color    receives the clear colour.
 * @return kQ3Success, or kQ3Failure with *color unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or color is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_GetClearImageColor(TQ3DrawContextObject context,
                                                            TQ3ColorARGB *color);

/**
 * Sets the pane of a draw context: the rectangle, in pixels, that rendering
 * is confined to while the pane state is kQ3True.
 *
 * @param context  the draw context to change.
 * @param pane     the pane; coordinates must be finite with min.x < max.x
 *                 and min.y < max.y.
 * @return kQ3Success, or kQ3Failure with the draw context unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or pane is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *   kQ3ErrorInvalidParameter   a coordinate is not finite, or the pane is
 *                              empty or inverted.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_SetPane(TQ3DrawContextObject context,
                                                 const TQ3Area *pane);

/**
 * Reads the pane of a draw context, as last set.
 *
 * @param context  the draw context to read.
 * @param pane     receives the pane.
 * @return kQ3Success, or kQ3Failure with *pane unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or pane is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_GetPane(TQ3DrawContextObject context, TQ3Area *pane);

/**
 * Turns the pane on (kQ3True: draw into the pane only) or off (kQ3False:
 * draw into the whole image). Turning it on checks the stored pane.
 *
 * @param context  the draw context to change.
 * @param state    the new pane state.
 * @return kQ3Success, or kQ3Failure with the draw context unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *   kQ3ErrorInvalidParameter   state is kQ3True and the stored pane has a
 *                              non-finite coordinate or is empty or inverted.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_SetPaneState(TQ3DrawContextObject context,
                                                      TQ3Boolean state);

/**
 * Reads the pane state of a draw context.
 *
 * @param context  the draw context to read.
 * @param state    receives kQ3True or kQ3False.
 * @return kQ3Success, or kQ3Failure with *state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or state is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_GetPaneState(TQ3DrawContextObject context,
                                                      TQ3Boolean *state);

/**
 * Sets what Q3View_StartRendering does to the image before drawing.
 *
 * @param context  the draw context to change.
 * @param method   kQ3ClearMethodNone or kQ3ClearMethodWithColor.
 * @return kQ3Success, or kQ3Failure with the draw context unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *   kQ3ErrorInvalidParameter   method is not a TQ3DrawContextClearImageMethod
 *                              value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_SetClearImageMethod(TQ3DrawContextObject context,
                                                             TQ3DrawContextClearImageMethod method);

/**
 * Reads the clear method of a draw context.
 *
 * @param context  the draw context to read.
 * @param method   receives the clear method.
 * @return kQ3Success, or kQ3Failure with *method unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or method is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_GetClearImageMethod(
    TQ3DrawContextObject context, TQ3DrawContextClearImageMethod *method);

/**
 * Sets the mask of a draw context (see TQ3DrawContextData); it takes effect
 * while the mask state is kQ3True.
 *
 * @param context  the draw context to change.
 * @param mask     the mask; it must obey the mask rules above. The struct
 *                 is copied, the bits it points to are not.
 * @return kQ3Success, or kQ3Failure with the draw context unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or mask is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *   kQ3ErrorInvalidParameter   *mask breaks a mask rule.
 *
 * Ownership: no references change; mask->image stays the caller's and must
 * stay valid while the mask state is on.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_SetMask(TQ3DrawContextObject context, const TQ3Bitmap *mask);

/**
 * Reads the mask of a draw context, as last set (all zero until set).
 *
 * @param context  the draw context to read.
 * @param mask     receives the mask; image is the pointer the caller gave.
 * @return kQ3Success, or kQ3Failure with *mask unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or mask is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *
 * Ownership: no references change; do not pass the result to Q3Bitmap_Empty.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_GetMask(TQ3DrawContextObject context, TQ3Bitmap *mask);

/**
 * Turns the mask on (kQ3True: write only the pixels the mask selects) or
 * off. Any nonzero value is stored as kQ3True. Turning it on checks the
 * stored mask.
 *
 * @param context  the draw context to change.
 * @param state    the new mask state.
 * @return kQ3Success, or kQ3Failure with the draw context unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *   kQ3ErrorInvalidParameter   state is on and the stored mask breaks a mask
 *                              rule (no mask was set).
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_SetMaskState(TQ3DrawContextObject context, TQ3Boolean state);

/**
 * Reads the mask state of a draw context (kQ3False until set).
 *
 * @param context  the draw context to read.
 * @param state    receives kQ3True or kQ3False.
 * @return kQ3Success, or kQ3Failure with *state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or state is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_GetMaskState(TQ3DrawContextObject context, TQ3Boolean *state);

/**
 * Records whether the application wants double buffering. Any nonzero value
 * is stored as kQ3True. The image is the same either way: Q3 always renders
 * offscreen and writes only the finished frame into the pixmap.
 *
 * @param context  the draw context to change.
 * @param state    the new double-buffer state.
 * @return kQ3Success, or kQ3Failure with the draw context unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_SetDoubleBufferState(TQ3DrawContextObject context, TQ3Boolean state);

/**
 * Reads the double-buffer state of a draw context, as last set.
 *
 * @param context  the draw context to read.
 * @param state    receives kQ3True or kQ3False.
 * @return kQ3Success, or kQ3Failure with *state unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      context or state is NULL.
 *   kQ3ErrorInvalidObject      context is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  context is not a draw context.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DrawContext_GetDoubleBufferState(TQ3DrawContextObject context, TQ3Boolean *state);

/* ---- Pixmap draw context ------------------------------------------------ */

/**
 * Creates a draw context that renders into a caller-owned pixmap.
 *
 * @param contextData  the common state, which must obey the
 *                     TQ3DrawContextData rules, and the pixmap, which must
 *                     obey the TQ3Pixmap rules (both above). The structure is
 *                     copied; the image memory is not.
 * @return the new draw context, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized         Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter          contextData is NULL.
 *   kQ3ErrorInvalidData            drawContextData breaks a
 *                                  TQ3DrawContextData rule.
 *   then the codes of the TQ3Pixmap rules, in their order:
 *   kQ3ErrorNULLParameter          pixmap.image is NULL.
 *   kQ3ErrorInvalidData            pixelType, byteOrder or bitOrder is not a
 *                                  value of its enumeration.
 *   kQ3ErrorUnsupportedPixelDepth  pixelSize does not fit pixelType.
 *   kQ3ErrorInvalidData            width or height is 0, or rowBytes is too
 *                                  small for a row.
 *   kQ3ErrorOutOfMemory            the draw context cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new draw context is born
 * with and releases it with Q3Object_Dispose. The image memory stays the
 * caller's and must outlive its use by the draw context.
 */
Q3_EXTERN_API_C(TQ3DrawContextObject) Q3PixmapDrawContext_New(
    const TQ3PixmapDrawContextData *contextData);

/**
 * Replaces the pixmap a pixmap draw context renders into.
 *
 * @param drawContext  the pixmap draw context to change.
 * @param pixmap       the new pixmap; it must obey the TQ3Pixmap rules above.
 *                     The structure is copied; the image memory is not.
 * @return kQ3Success, or kQ3Failure with the draw context unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized         Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter          drawContext or pixmap is NULL.
 *   kQ3ErrorInvalidObject          drawContext is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType      drawContext is not a pixmap draw context.
 *   then the codes of the TQ3Pixmap rules, in their order:
 *   kQ3ErrorNULLParameter          pixmap->image is NULL.
 *   kQ3ErrorInvalidData            pixelType, byteOrder or bitOrder is not a
 *                                  value of its enumeration.
 *   kQ3ErrorUnsupportedPixelDepth  pixelSize does not fit pixelType.
 *   kQ3ErrorInvalidData            width or height is 0, or rowBytes is too
 *                                  small for a row.
 *
 * Ownership: no references change. Q3 stops using the previous image memory
 * once no view is rendering into the draw context with it; the new memory
 * stays the caller's and must outlive its use by the draw context.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapDrawContext_SetPixmap(TQ3DrawContextObject drawContext,
                                                         const TQ3Pixmap *pixmap);

/**
 * Reads the pixmap a pixmap draw context renders into.
 *
 * @param drawContext  the pixmap draw context to read.
 * @param pixmap       receives the pixmap as last set (image is the caller's
 *                     pointer).
 * @return kQ3Success, or kQ3Failure with *pixmap unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      drawContext or pixmap is NULL.
 *   kQ3ErrorInvalidObject      drawContext is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  drawContext is not a pixmap draw context.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PixmapDrawContext_GetPixmap(TQ3DrawContextObject drawContext,
                                                         TQ3Pixmap *pixmap);

#if defined(WINDOW_SYSTEM_X11) && WINDOW_SYSTEM_X11

/* ---- X11 draw context ---------------------------------------------------
 *
 * Renders a view into an X window. Q3 draws each frame off screen with its
 * rendering backend (the same drawing, and so the same pixels, as a pixmap
 * draw context of the window's size) and puts the finished pane into the
 * window with one XPutImage at Q3View_EndRendering, so the window never
 * shows a partial frame, with or without double buffering. The window's
 * size is read from the server at every Q3View_StartRendering, so the
 * frame follows a resized window. The window's visual must be TrueColor;
 * libX11.so.6 is opened when first needed. X protocol errors from these
 * calls (BadWindow, BadDrawable, BadMatch) are caught by an error handler
 * Q3 installs around its own requests (and restores afterwards), and
 * become kQ3ErrorX11Error; they never reach the application's handler or
 * end the process. Xlib calls on one Display must not run on two threads
 * at once (XInitThreads otherwise).
 */

/* Apple's buffer record for Q3XBuffers_New/Swap. */
typedef struct OpaqueTQ3XBufferObject *TQ3XBufferObject;

/* A PseudoColor colormap's layout (Apple's; stored, unused by TrueColor). */
struct TQ3XColormapData {
    long baseEntry;
    long maxRed;
    long maxGreen;
    long maxBlue;
    long multRed;
    long multGreen;
    long multBlue;
};
typedef struct TQ3XColormapData TQ3XColormapData;

/*
 * An X11 draw context's data. display: not NULL. drawable: a window of that
 * display (checked with the server). visual: NULL (the window's own visual
 * is used) or a TrueColor visual. cmap: stored. colorMapData: NULL or a
 * colormap layout, copied.
 */
struct TQ3XDrawContextData {
    TQ3DrawContextData contextData;
    Display *display;
    Drawable drawable;
    Visual *visual;
    Colormap cmap;
    TQ3XColormapData *colorMapData;
};
typedef struct TQ3XDrawContextData TQ3XDrawContextData;

/**
 * Makes a buffer record for a window, for programs that swap buffers
 * themselves. Q3 composes every frame off screen and shows it whole, so
 * the record only remembers the display, window and count; Q3XBuffers_Swap
 * sends the display's queued requests. The same display and window always
 * give the same record, which lives as long as the process (Apple declares
 * no call to dispose of it).
 *
 * @param dpy         the display.
 * @param numBuffers  1 or 2.
 * @param window      a window of dpy.
 * @return the record, or NULL.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     dpy is NULL.
 *   kQ3ErrorInvalidParameter  numBuffers is neither 1 nor 2.
 *   kQ3ErrorX11Error          window is not a window of dpy, or libX11
 *                             cannot be loaded.
 *
 * Ownership: the record is Q3's.
 */
Q3_EXTERN_API_C(TQ3XBufferObject) Q3XBuffers_New(Display *dpy, unsigned long numBuffers, Window window);

/**
 * Shows what was drawn into the record's window: flushes the display's
 * queued requests (XFlush).
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     dpy or buffers is NULL.
 *   kQ3ErrorInvalidParameter  buffers did not come from Q3XBuffers_New, or
 *                             was made for another display.
 *
 * Ownership: none.
 */
Q3_EXTERN_API_C(void) Q3XBuffers_Swap(Display *dpy, TQ3XBufferObject buffers);

/**
 * Finds the visuals of a screen an X11 draw context can use: TrueColor,
 * depth 24.
 *
 * @param dpy     the display.
 * @param screen  one of its screens.
 * @return the first of Xlib's list of matching visuals, or NULL.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   dpy or screen is NULL.
 *   kQ3ErrorX11Error        the screen has no such visual, or libX11 cannot
 *                           be loaded.
 *
 * Ownership: the caller frees the list with XFree.
 */
Q3_EXTERN_API_C(XVisualInfo *) Q3X_GetVisualInfo(Display *dpy, Screen *screen);

/**
 * Creates an X11 draw context.
 *
 * @param xContextData  the common data and the window (TQ3XDrawContextData).
 * @return a new draw context, or NULL.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   xContextData or its display is NULL.
 *   kQ3ErrorInvalidData     the TQ3DrawContextData rules (see
 *                           Q3PixmapDrawContext_New), or visual is not
 *                           TrueColor.
 *   kQ3ErrorX11Error        drawable is not a window of display, or libX11
 *                           cannot be loaded.
 *
 * Ownership: the caller owns the one reference to the new draw context.
 * The display, window, visual and colormap stay the caller's and must
 * outlive the draw context's use.
 */
Q3_EXTERN_API_C(TQ3DrawContextObject) Q3XDrawContext_New(const TQ3XDrawContextData *xContextData);

/**
 * Sets or reads one field of an X11 draw context's data. Set checks as
 * Q3XDrawContext_New does for that field (a new display is not checked
 * against the drawable: set the drawable next) and changes nothing on
 * failure; Get returns the field as last set (the colormap data as a
 * copy; all zero when none was given).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      drawContext, or the pointer argument, is NULL.
 *   kQ3ErrorInvalidObject      drawContext is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  drawContext is not an X11 draw context.
 *   kQ3ErrorInvalidParameter   SetVisual: the visual is not TrueColor.
 *   kQ3ErrorX11Error           SetDrawable: not a window of the display.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3XDrawContext_SetDisplay(TQ3DrawContextObject drawContext, const Display *display);
Q3_EXTERN_API_C(TQ3Status) Q3XDrawContext_GetDisplay(TQ3DrawContextObject drawContext, Display **display);
Q3_EXTERN_API_C(TQ3Status) Q3XDrawContext_SetDrawable(TQ3DrawContextObject drawContext, Drawable drawable);
Q3_EXTERN_API_C(TQ3Status) Q3XDrawContext_GetDrawable(TQ3DrawContextObject drawContext, Drawable *drawable);
Q3_EXTERN_API_C(TQ3Status) Q3XDrawContext_SetVisual(TQ3DrawContextObject drawContext, const Visual *visual);
Q3_EXTERN_API_C(TQ3Status) Q3XDrawContext_GetVisual(TQ3DrawContextObject drawContext, Visual **visual);
Q3_EXTERN_API_C(TQ3Status) Q3XDrawContext_SetColormap(TQ3DrawContextObject drawContext, Colormap colormap);
Q3_EXTERN_API_C(TQ3Status) Q3XDrawContext_GetColormap(TQ3DrawContextObject drawContext, Colormap *colormap);
Q3_EXTERN_API_C(TQ3Status) Q3XDrawContext_SetColormapData(TQ3DrawContextObject drawContext,
                                                          const TQ3XColormapData *colormapData);
Q3_EXTERN_API_C(TQ3Status) Q3XDrawContext_GetColormapData(TQ3DrawContextObject drawContext,
                                                          TQ3XColormapData *colormapData);

#endif /* WINDOW_SYSTEM_X11 */

#ifdef __cplusplus
}
#endif

#endif /* QD3DDRAWCONTEXT_H */
