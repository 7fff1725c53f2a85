// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Q3's OpenGL entry points, resolved through the backend's own loader
// (OSMesaGetProcAddress, eglGetProcAddress) into a table, never bound by
// global name. A program that links libGL (SDL, GLFW, Qt) would otherwise
// bind Q3's gl* calls to libGL's dispatch, which draws into whatever context
// the program has current, or crashes; so libq3.so imports no gl* symbol
// (tests/abi/CheckGlImports.cmake checks it).
//
// Include this header instead of <GL/gl.h>: it declares the GL types and
// enums as usual, and for every name of the list below a q3::glFoo with
// glFoo's exact parameters that calls through the table of the context
// current on this thread. Code in namespace q3 finds q3::glFoo before the
// global prototype (unqualified lookup stops at the first scope that has the
// name; GL's arguments are never of class type, so argument-dependent lookup
// adds nothing), so call sites keep their plain spelling,
// glDrawElements(...). A backend binds its table with GlApiScope while its
// context is current (render/GlContext.h).
//
// A new GL function is one line in Q3_GL_FUNCTIONS (its name without the gl
// prefix; its type comes from the Khronos headers). A gl* call not in the
// list still compiles, against the global prototype, and the test
// Abi.SharedLibraryImportsNoGlSymbol then names it.

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#define Q3_GL_FUNCTIONS(X) \
    X(ActiveTexture) \
    X(AlphaFunc) \
    X(AttachShader) \
    X(Begin) \
    X(BindAttribLocation) \
    X(BindBuffer) \
    X(BindFragDataLocationIndexed) \
    X(BindFramebuffer) \
    X(BindRenderbuffer) \
    X(BindTexture) \
    X(BlendFuncSeparate) \
    X(BlitFramebuffer) \
    X(BufferData) \
    X(BufferSubData) \
    X(CheckFramebufferStatus) \
    X(Clear) \
    X(ClearColor) \
    X(ClearDepth) \
    X(Color3f) \
    X(ColorMask) \
    X(ColorPointer) \
    X(CompileShader) \
    X(CopyTexImage2D) \
    X(CreateProgram) \
    X(CreateShader) \
    X(CullFace) \
    X(DeleteBuffers) \
    X(DeleteFramebuffers) \
    X(DeleteProgram) \
    X(DeleteShader) \
    X(DeleteTextures) \
    X(DepthFunc) \
    X(DepthMask) \
    X(Disable) \
    X(DisableClientState) \
    X(DisableVertexAttribArray) \
    X(DrawArrays) \
    X(DrawElements) \
    X(DrawRangeElements) \
    X(Enable) \
    X(EnableClientState) \
    X(EnableVertexAttribArray) \
    X(End) \
    X(Finish) \
    X(FramebufferRenderbuffer) \
    X(FramebufferTexture2D) \
    X(FrontFace) \
    X(GenBuffers) \
    X(GenFramebuffers) \
    X(GenRenderbuffers) \
    X(GenTextures) \
    X(GetError) \
    X(GetIntegerv) \
    X(GetProgramInfoLog) \
    X(GetProgramiv) \
    X(GetShaderInfoLog) \
    X(GetShaderiv) \
    X(GetString) \
    X(GetUniformLocation) \
    X(IsEnabled) \
    X(LineWidth) \
    X(LinkProgram) \
    X(LoadIdentity) \
    X(LoadMatrixf) \
    X(MatrixMode) \
    X(MultiDrawArrays) \
    X(MultiDrawElements) \
    X(NormalPointer) \
    X(PixelStorei) \
    X(PointSize) \
    X(PolygonMode) \
    X(ReadBuffer) \
    X(ReadPixels) \
    X(RenderbufferStorageMultisample) \
    X(Scissor) \
    X(ShadeModel) \
    X(ShaderSource) \
    X(TexCoordPointer) \
    X(TexEnvi) \
    X(TexImage2D) \
    X(TexParameteri) \
    X(Uniform1f) \
    X(Uniform1fv) \
    X(Uniform1i) \
    X(Uniform1iv) \
    X(Uniform3fv) \
    X(Uniform4fv) \
    X(UniformMatrix3fv) \
    X(UniformMatrix4fv) \
    X(UseProgram) \
    X(Vertex2f) \
    X(VertexAttrib4f) \
    X(VertexAttribPointer) \
    X(VertexPointer) \
    X(Viewport)

namespace q3 {

/// One backend's OpenGL entry points. Invariant after a successful load():
/// every member is non-null.
struct GlApi {
#define Q3_GL_MEMBER(name) decltype(&::gl##name) name = nullptr;
    Q3_GL_FUNCTIONS(Q3_GL_MEMBER)
#undef Q3_GL_MEMBER

    /// Resolves every function of the list with `getProcAddress` ("glClear"
    /// and so on). False, with the first missing name in `missing`, when
    /// one is not found (the table is then unusable).
    using GetProcAddress = void* (*)(const char* name, void* loader);
    bool load(GetProcAddress getProcAddress, void* loader, const char*& missing);
};

/// The table of the context current on this thread (GlApiScope); using a
/// gl* name without one is a programming error (asserted in debug builds).
const GlApi& gl();

/// Makes `api` the thread's table for the lifetime of the scope, then the
/// previous one again (scopes nest, as contexts do).
class GlApiScope {
public:
    explicit GlApiScope(const GlApi* api);
    ~GlApiScope();
    GlApiScope(const GlApiScope&) = delete;
    GlApiScope& operator=(const GlApiScope&) = delete;

private:
    const GlApi* m_previous;
};

template <auto member>
struct GlCall;
template <class R, class... Args, R (*GlApi::*member)(Args...)>
struct GlCall<member> {
    static R call(Args... args) { return (gl().*member)(args...); }
};

#define Q3_GL_CALL(name) inline constexpr auto gl##name = &GlCall<&GlApi::name>::call;
Q3_GL_FUNCTIONS(Q3_GL_CALL)
#undef Q3_GL_CALL

} // namespace q3

