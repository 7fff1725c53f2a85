/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Q3GLDrawContext.h: Q3 extension. A draw context that puts each frame into
 * the framebuffer of the application's own OpenGL context, for programs that
 * own their window and context through SDL, GLFW, Qt, GLX or EGL (the game
 * ports did this with Quesa's SDL draw context). QuickDraw 3D never had it.
 *
 * The context used is whichever the application has made current on the
 * thread that calls Q3View_StartRendering and Q3View_EndRendering, through
 * EGL or GLX; OpenGL 3.0 or OpenGL ES 3.0 at least. Q3 draws the frame in its
 * own context, as into a pixmap of the draw context's size, and at
 * Q3View_EndRendering copies the pane (the whole framebuffer when the pane
 * state is off) into the framebuffer the application has bound to
 * GL_DRAW_FRAMEBUFFER (its window's, 0, or a framebuffer object of its
 * own), without swapping buffers. The pixels are exactly those a pixmap
 * draw context of the same size and data receives. The application draws
 * before and after in the same frame (a background, overlays) and swaps when
 * it likes.
 *
 * The draw context data apply as to a pixmap: kQ3ClearMethodWithColor
 * clears the pane to the clear colour; kQ3ClearMethodNone and a mask leave
 * the framebuffer's other pixels as the application drew them (Q3 reads the
 * pane back first). The framebuffer must be single-sample. The pane is in
 * the framebuffer's pixels, y measured from the top, as QuickDraw 3D's.
 *
 * GL state: a frame leaves the application's context current and every GL
 * state as it found them. Only the read-framebuffer binding, the active
 * unit's GL_TEXTURE_2D binding, the pixel pack and unpack buffer bindings
 * and parameters, the read buffer of the bound framebuffer, GL_SCISSOR_TEST
 * and GL_FRAMEBUFFER_SRGB are changed, each set back before the call returns
 * (docs/gl-draw-context.md lists them); glGetError is never called, so the
 * application's pending error stays.
 */
#ifndef Q3GLDRAWCONTEXT_H
#define Q3GLDRAWCONTEXT_H

#include "QD3D.h"
#include "QD3DDrawContext.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Q3 extension constants.
 *
 * kQ3DrawContextTypeGL
 *   The type of a GL draw context (Q3DrawContext_GetType).
 * kQ3GLDrawContextMaxSize
 *   The largest width and height of a GL draw context: 16384 pixels, the
 *   largest image Q3 renders.
 */
#define kQ3DrawContextTypeGL Q3_OBJECT_TYPE('d', 'g', 'l', 'c')
#define kQ3GLDrawContextMaxSize 16384UL

/*
 * Q3 extension. What a GL draw context is made from.
 *
 * drawContextData  as for every draw context (QD3DDrawContext.h); the pane
 *                  is in the framebuffer's pixels, y from the top.
 * width, height    the size in pixels of the framebuffer the application
 *                  binds (for a window: its drawable size, such as
 *                  SDL_GL_GetDrawableSize gives); 1 to
 *                  kQ3GLDrawContextMaxSize. Q3 cannot ask OpenGL for it.
 */
typedef struct TQ3GLDrawContextData {
    TQ3DrawContextData drawContextData;
    TQ3Uns32 width;
    TQ3Uns32 height;
} TQ3GLDrawContextData;

/**
 * Q3 extension. Creates a GL draw context. No OpenGL context need be current
 * now: it is looked for at each Q3View_StartRendering.
 *
 * @param contextData  the draw context's data, copied.
 * @return the new draw context, or NULL.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   contextData is NULL.
 *   kQ3ErrorInvalidData     drawContextData breaks a rule of
 *                           QD3DDrawContext.h (pane, mask, an enumeration),
 *                           or width or height is 0 or above
 *                           kQ3GLDrawContextMaxSize.
 *
 * Rendering into it, Q3View_StartRendering posts kQ3ErrorBadDrawContext
 * and fails when no OpenGL context is current on the thread, it is older
 * than OpenGL 3.0 / OpenGL ES 3.0, or its bound draw framebuffer is
 * multisampled (or, without a clear or with a mask, cannot be read back);
 * Q3View_EndRendering posts
 * kQ3ErrorBadDrawContext when the frame cannot be put into the framebuffer.
 *
 * Ownership: the caller holds the one reference to the new object.
 */
Q3_EXTERN_API_C(TQ3DrawContextObject) Q3GLDrawContext_New(const TQ3GLDrawContextData *contextData);

/**
 * Q3 extension. Sets the size of the framebuffer the draw context draws
 * into, as when the application's window is resized. The pane is kept.
 *
 * @param drawContext  a GL draw context.
 * @param width        1 to kQ3GLDrawContextMaxSize pixels.
 * @param height       1 to kQ3GLDrawContextMaxSize pixels.
 * @return kQ3Success, or kQ3Failure with the draw context unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      drawContext is NULL.
 *   kQ3ErrorInvalidObject      drawContext is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  drawContext is not a GL draw context.
 *   kQ3ErrorInvalidParameter   width or height is 0 or above
 *                              kQ3GLDrawContextMaxSize.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GLDrawContext_SetSize(TQ3DrawContextObject drawContext, TQ3Uns32 width,
                                                   TQ3Uns32 height);

/**
 * Q3 extension. Gets the size set by Q3GLDrawContext_New or _SetSize.
 *
 * @param drawContext  a GL draw context.
 * @param width        receives the width in pixels.
 * @param height       receives the height in pixels.
 * @return kQ3Success, or kQ3Failure with the outputs unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      drawContext, width or height is NULL.
 *   kQ3ErrorInvalidObject      drawContext is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  drawContext is not a GL draw context.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GLDrawContext_GetSize(TQ3DrawContextObject drawContext, TQ3Uns32 *width,
                                                   TQ3Uns32 *height);

#ifdef __cplusplus
}
#endif

#endif
