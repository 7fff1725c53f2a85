/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef QD3D_H
#define QD3D_H

/*
 * QD3D.h: QuickDraw 3D's base types, object type codes and the object,
 * shared-object and system calls. Names, values and layouts are QuickDraw 3D
 * 1.6's; anything QuickDraw 3D never had is marked "Q3 extension".
 *
 * Every object handle type (TQ3GeometryObject, TQ3ViewObject, ...) is a
 * typedef of TQ3Object, as in QuickDraw 3D, so legacy code may pass any of
 * them where another is expected; Q3 checks the class of each handle at run
 * time and posts kQ3ErrorInvalidObjectType when it does not fit.
 */

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Declares a public entry point. Only these symbols are exported from libq3. */
#if defined(Q3_BUILDING_LIBRARY) && defined(__GNUC__)
#define Q3_EXTERN_API_C(_type) extern __attribute__((visibility("default"))) _type
#else
#define Q3_EXTERN_API_C(_type) extern _type
#endif

/* ---- Platform ----------------------------------------------------------- */

/*
 * Apple's platform switches, as QD3D.h defines them for a Unix target (Q3
 * runs on Linux), for legacy code that tests them with #if. QD3D_EXPORT,
 * QD3D_CALL and QD3D_CALLBACK are empty outside Win32, as in QD3D.h.
 * WINDOW_SYSTEM_X11 is 1: QD3DDrawContext.h declares Apple's X11 draw
 * context (TQ3XDrawContextData, Q3XDrawContext_New, Q3XBuffers_New, ...)
 * and, as Apple's header does, includes <X11/Xlib.h> and <X11/Xutil.h> for
 * it. A program built where the X11 headers are missing defines
 * WINDOW_SYSTEM_X11 to 0 before including a Q3 header (the library is the
 * same either way).
 */
#define OS_MACINTOSH 0
#define OS_WIN32 0
#define OS_UNIX 1
#define OS_NEXT 0
#define WINDOW_SYSTEM_MACINTOSH 0
#define WINDOW_SYSTEM_WIN32 0
#ifndef WINDOW_SYSTEM_X11
#define WINDOW_SYSTEM_X11 1
#endif
#define WINDOW_SYSTEM_NEXT 0

#define QD3D_EXPORT
#define QD3D_CALL
#define QD3D_CALLBACK

/* ---- Basic types -------------------------------------------------------- */

/*
 * Apple's fixed-size names (QuickDraw 3D 1.6 declares them in QD3DIO.h, which
 * includes QD3D.h; Q3 declares them here, where later code expects them).
 * Each is exactly the width its name says (<stdint.h>), as it was on the
 * Macintosh, where Apple's unsigned long was 32 bits: legacy code lays out
 * binary data (pixmap images, file records) in TQ3Uns32 arrays. Apple's own
 * parameters and struct fields typed unsigned long stay unsigned long, so
 * code that passes an unsigned long * to a getter keeps compiling; only the
 * names with a width in them changed meaning on LP64 (docs/porting.md,
 * "Types"). The 64-bit types keep Apple's layout: structs of two 32-bit
 * halves, high half first on big-endian machines, low half first here.
 */
typedef uint8_t TQ3Uns8;
typedef int8_t TQ3Int8;
typedef uint16_t TQ3Uns16;
typedef int16_t TQ3Int16;
typedef uint32_t TQ3Uns32;
typedef int32_t TQ3Int32;
#if defined(__BYTE_ORDER__) && defined(__ORDER_BIG_ENDIAN__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
typedef struct TQ3Uns64 { TQ3Uns32 hi; TQ3Uns32 lo; } TQ3Uns64;
typedef struct TQ3Int64 { TQ3Int32 hi; TQ3Uns32 lo; } TQ3Int64;
#else
typedef struct TQ3Uns64 { TQ3Uns32 lo; TQ3Uns32 hi; } TQ3Uns64;
typedef struct TQ3Int64 { TQ3Uns32 lo; TQ3Int32 hi; } TQ3Int64;
#endif
typedef float TQ3Float32;
typedef double TQ3Float64;
typedef TQ3Uns32 TQ3Size;

/* ---- Objects ------------------------------------------------------------ */

typedef long TQ3ObjectType;
typedef struct OpaqueTQ3Object *TQ3Object;

typedef TQ3Object TQ3ElementObject;
typedef TQ3Object TQ3SharedObject;
typedef TQ3Object TQ3ViewObject;
typedef TQ3Object TQ3PickObject;

typedef TQ3SharedObject TQ3RendererObject;
typedef TQ3SharedObject TQ3DrawContextObject;
typedef TQ3SharedObject TQ3SetObject;
typedef TQ3SharedObject TQ3FileObject;
typedef TQ3SharedObject TQ3ShapeObject;
typedef TQ3SharedObject TQ3ShapePartObject;
typedef TQ3SharedObject TQ3ControllerStateObject;
typedef TQ3SharedObject TQ3TrackerObject;
typedef TQ3SharedObject TQ3StringObject;
typedef TQ3SharedObject TQ3StorageObject;
typedef TQ3SharedObject TQ3TextureObject;
typedef TQ3SharedObject TQ3ViewHintsObject;

typedef TQ3SetObject TQ3AttributeSet;

typedef TQ3ShapeObject TQ3GroupObject;
typedef TQ3ShapeObject TQ3GeometryObject;
typedef TQ3ShapeObject TQ3ShaderObject;
typedef TQ3ShapeObject TQ3StyleObject;
typedef TQ3ShapeObject TQ3TransformObject;
typedef TQ3ShapeObject TQ3LightObject;
typedef TQ3ShapeObject TQ3CameraObject;
typedef TQ3ShapeObject TQ3UnknownObject;
typedef TQ3ShapeObject TQ3ReferenceObject;
typedef TQ3ShapeObject TQ3StateOperatorObject;

typedef TQ3ShapePartObject TQ3MeshPartObject;
typedef TQ3MeshPartObject TQ3MeshFacePartObject;
typedef TQ3MeshPartObject TQ3MeshEdgePartObject;
typedef TQ3MeshPartObject TQ3MeshVertexPartObject;

typedef TQ3GroupObject TQ3DisplayGroupObject;
typedef TQ3ShaderObject TQ3SurfaceShaderObject;
typedef TQ3ShaderObject TQ3IlluminationShaderObject;

/* A position of an object in a group (QD3DGroup.h). */
typedef struct OpaqueTQ3GroupPosition *TQ3GroupPosition;
/* A controller's reference (QuickDraw 3D's controller API, which Q3 lacks). */
typedef void *TQ3ControllerRef;

enum { kQ3StringMaximumLength = 1024 };
typedef char TQ3ObjectClassNameString[kQ3StringMaximumLength];

/* ---- Flags and switches ------------------------------------------------- */

typedef enum TQ3Boolean { kQ3False = 0, kQ3True = 1 } TQ3Boolean;
typedef enum TQ3Switch { kQ3Off = 0, kQ3On = 1 } TQ3Switch;
typedef enum TQ3Status { kQ3Failure = 0, kQ3Success = 1 } TQ3Status;
typedef enum TQ3Axis { kQ3AxisX = 0, kQ3AxisY = 1, kQ3AxisZ = 2 } TQ3Axis;

/* Pixel layouts of a TQ3Pixmap; see QD3DDrawContext.h for how Q3 writes each. */
typedef enum TQ3PixelType {
    kQ3PixelTypeRGB32 = 0,     /* alpha:8 (ignored), R:8, G:8, B:8 */
    kQ3PixelTypeARGB32 = 1,    /* alpha:8, R:8, G:8, B:8 */
    kQ3PixelTypeRGB16 = 2,     /* alpha:1 (ignored), R:5, G:5, B:5 */
    kQ3PixelTypeARGB16 = 3,    /* alpha:1, R:5, G:5, B:5 */
    kQ3PixelTypeRGB16_565 = 4, /* R:5, G:6, B:5 */
    kQ3PixelTypeRGB24 = 5      /* R:8, G:8, B:8 */
} TQ3PixelType;

typedef enum TQ3Endian { kQ3EndianBig = 0, kQ3EndianLittle = 1 } TQ3Endian;

typedef enum TQ3EndCapMasks {
    kQ3EndCapNone = 0,
    kQ3EndCapMaskTop = 1 << 0,
    kQ3EndCapMaskBottom = 1 << 1,
    kQ3EndCapMaskInterior = 1 << 2
} TQ3EndCapMasks;
typedef unsigned long TQ3EndCap;

enum { kQ3ArrayIndexNULL = ~0 };

/* ---- Points, vectors, colors -------------------------------------------- */

typedef struct TQ3Vector2D { float x, y; } TQ3Vector2D;
typedef struct TQ3Vector3D { float x, y, z; } TQ3Vector3D;
typedef struct TQ3Point2D { float x, y; } TQ3Point2D;
typedef struct TQ3Point3D { float x, y, z; } TQ3Point3D;
/* A homogeneous point: its position is (x/w, y/w, z/w). */
typedef struct TQ3RationalPoint4D { float x, y, z, w; } TQ3RationalPoint4D;
typedef struct TQ3RationalPoint3D { float x, y, w; } TQ3RationalPoint3D;
typedef struct TQ3Quaternion { float w, x, y, z; } TQ3Quaternion;
typedef struct TQ3Ray3D { TQ3Point3D origin; TQ3Vector3D direction; } TQ3Ray3D;
typedef struct TQ3Param2D { float u, v; } TQ3Param2D;
typedef struct TQ3Param3D { float u, v, w; } TQ3Param3D;
typedef struct TQ3Tangent2D { TQ3Vector3D uTangent, vTangent; } TQ3Tangent2D;
typedef struct TQ3Tangent3D { TQ3Vector3D uTangent, vTangent, wTangent; } TQ3Tangent3D;
typedef struct TQ3PolarPoint { float r, theta; } TQ3PolarPoint;
typedef struct TQ3SphericalPoint { float rho, theta, phi; } TQ3SphericalPoint;
typedef struct TQ3ColorRGB { float r, g, b; } TQ3ColorRGB;
typedef struct TQ3ColorARGB { float a, r, g, b; } TQ3ColorARGB;

typedef struct TQ3Vertex3D {
    TQ3Point3D point;
    TQ3AttributeSet attributeSet;
} TQ3Vertex3D;

/* Matrices act on row vectors, as in QuickDraw 3D: p' = p * M, so the
 * translation of a 4x4 matrix sits in value[3][0..2]. */
typedef struct TQ3Matrix3x3 { float value[3][3]; } TQ3Matrix3x3;
typedef struct TQ3Matrix4x4 { float value[4][4]; } TQ3Matrix4x4;

/* ---- Images ------------------------------------------------------------- */

typedef struct TQ3Pixmap {
    void *image;             /* top row first; rowBytes apart */
    unsigned long width;
    unsigned long height;
    unsigned long rowBytes;
    unsigned long pixelSize; /* bits per pixel: 16, 24 or 32 as pixelType says */
    TQ3PixelType pixelType;
    TQ3Endian bitOrder;
    TQ3Endian byteOrder;
} TQ3Pixmap;

typedef struct TQ3StoragePixmap {
    TQ3StorageObject image;
    unsigned long width;
    unsigned long height;
    unsigned long rowBytes;
    unsigned long pixelSize;
    TQ3PixelType pixelType;
    TQ3Endian bitOrder;
    TQ3Endian byteOrder;
} TQ3StoragePixmap;

typedef struct TQ3Bitmap {
    unsigned char *image;
    unsigned long width;
    unsigned long height;
    unsigned long rowBytes;
    TQ3Endian bitOrder;
} TQ3Bitmap;

/* One image of a mipmap texture (QD3DShader.h): width x height pixels,
 * rowBytes apart, starting offset bytes into the mipmap's storage. */
typedef struct TQ3MipmapImage {
    unsigned long width;
    unsigned long height;
    unsigned long rowBytes;
    unsigned long offset;
} TQ3MipmapImage;

/* A mipmap texture's data (Q3MipmapTexture_New): one storage object holding
 * every image; useMipmapping says whether mipmaps[1..] are given too (each
 * half the size of the one before, down to 1 x 1); reserved must be 0. */
typedef struct TQ3Mipmap {
    TQ3StorageObject image;
    TQ3Boolean useMipmapping;
    TQ3PixelType pixelType;
    TQ3Endian bitOrder;
    TQ3Endian byteOrder;
    unsigned long reserved;
    TQ3MipmapImage mipmaps[32];
} TQ3Mipmap;

/* ---- Areas and bounds --------------------------------------------------- */

typedef struct TQ3Area { TQ3Point2D min, max; } TQ3Area;
typedef struct TQ3PlaneEquation { TQ3Vector3D normal; float constant; } TQ3PlaneEquation;
typedef struct TQ3BoundingBox { TQ3Point3D min, max; TQ3Boolean isEmpty; } TQ3BoundingBox;
typedef struct TQ3BoundingSphere { TQ3Point3D origin; float radius; TQ3Boolean isEmpty; } TQ3BoundingSphere;

/* How Q3View_StartBoundingBox/Sphere bound a shape: Exact transforms every
 * point to world space; Approximate transforms the local bounds' corners. */
typedef enum TQ3ComputeBounds {
    kQ3ComputeBoundsExact = 0,
    kQ3ComputeBoundsApproximate = 1
} TQ3ComputeBounds;

/* ---- Sets --------------------------------------------------------------- */

typedef long TQ3ElementType;
enum { kQ3ElementTypeNone = 0, kQ3ElementTypeUnknown = 32, kQ3ElementTypeSet = 33 };

/* ---- Object type codes -------------------------------------------------- */

#define Q3_FOUR_CHARACTER_CONSTANT(a, b, c, d)                                       \
    ((unsigned long)(((unsigned long)(a) << 24) | ((unsigned long)(b) << 16) |       \
                     ((unsigned long)(c) << 8) | ((unsigned long)(d))))
#define Q3_OBJECT_TYPE(a, b, c, d) ((TQ3ObjectType)Q3_FOUR_CHARACTER_CONSTANT(a, b, c, d))

#define kQ3ObjectTypeInvalid 0L
#define kQ3ObjectTypeView Q3_OBJECT_TYPE('v', 'i', 'e', 'w')
#define kQ3ObjectTypeElement Q3_OBJECT_TYPE('e', 'l', 'm', 'n')
#define kQ3ElementTypeAttribute Q3_OBJECT_TYPE('e', 'a', 't', 't')
#define kQ3ObjectTypePick Q3_OBJECT_TYPE('p', 'i', 'c', 'k')
#define kQ3PickTypeWindowPoint Q3_OBJECT_TYPE('p', 'k', 'w', 'p')
#define kQ3PickTypeWindowRect Q3_OBJECT_TYPE('p', 'k', 'w', 'r')
#define kQ3PickTypeWorldRay Q3_OBJECT_TYPE('p', 'k', 'r', 'y')
#define kQ3ObjectTypeShared Q3_OBJECT_TYPE('s', 'h', 'r', 'd')
#define kQ3SharedTypeRenderer Q3_OBJECT_TYPE('r', 'd', 'd', 'r')
#define kQ3RendererTypeWireFrame Q3_OBJECT_TYPE('w', 'r', 'f', 'r')
#define kQ3RendererTypeGeneric Q3_OBJECT_TYPE('g', 'n', 'r', 'r')
#define kQ3RendererTypeInteractive Q3_OBJECT_TYPE('c', 't', 'w', 'n')
#define kQ3SharedTypeShape Q3_OBJECT_TYPE('s', 'h', 'a', 'p')
#define kQ3ShapeTypeGeometry Q3_OBJECT_TYPE('g', 'm', 't', 'r')
#define kQ3GeometryTypeBox Q3_OBJECT_TYPE('b', 'o', 'x', ' ')
#define kQ3GeometryTypeGeneralPolygon Q3_OBJECT_TYPE('g', 'p', 'g', 'n')
#define kQ3GeometryTypeLine Q3_OBJECT_TYPE('l', 'i', 'n', 'e')
#define kQ3GeometryTypeMarker Q3_OBJECT_TYPE('m', 'r', 'k', 'r')
#define kQ3GeometryTypePixmapMarker Q3_OBJECT_TYPE('m', 'r', 'k', 'p')
#define kQ3GeometryTypeMesh Q3_OBJECT_TYPE('m', 'e', 's', 'h')
#define kQ3GeometryTypeNURBCurve Q3_OBJECT_TYPE('n', 'r', 'b', 'c')
#define kQ3GeometryTypeNURBPatch Q3_OBJECT_TYPE('n', 'r', 'b', 'p')
#define kQ3GeometryTypePoint Q3_OBJECT_TYPE('p', 'n', 't', ' ')
#define kQ3GeometryTypePolygon Q3_OBJECT_TYPE('p', 'l', 'y', 'g')
#define kQ3GeometryTypePolyLine Q3_OBJECT_TYPE('p', 'l', 'y', 'l')
#define kQ3GeometryTypeTriangle Q3_OBJECT_TYPE('t', 'r', 'n', 'g')
#define kQ3GeometryTypeTriGrid Q3_OBJECT_TYPE('t', 'r', 'i', 'g')
#define kQ3GeometryTypeCone Q3_OBJECT_TYPE('c', 'o', 'n', 'e')
#define kQ3GeometryTypeCylinder Q3_OBJECT_TYPE('c', 'y', 'l', 'n')
#define kQ3GeometryTypeDisk Q3_OBJECT_TYPE('d', 'i', 's', 'k')
#define kQ3GeometryTypeEllipse Q3_OBJECT_TYPE('e', 'l', 'p', 's')
#define kQ3GeometryTypeEllipsoid Q3_OBJECT_TYPE('e', 'l', 'p', 'd')
#define kQ3GeometryTypePolyhedron Q3_OBJECT_TYPE('p', 'l', 'h', 'd')
#define kQ3GeometryTypeTorus Q3_OBJECT_TYPE('t', 'o', 'r', 's')
#define kQ3GeometryTypeTriMesh Q3_OBJECT_TYPE('t', 'm', 's', 'h')
#define kQ3ShapeTypeShader Q3_OBJECT_TYPE('s', 'h', 'd', 'r')
#define kQ3ShaderTypeSurface Q3_OBJECT_TYPE('s', 'u', 's', 'h')
#define kQ3SurfaceShaderTypeTexture Q3_OBJECT_TYPE('t', 'x', 's', 'u')
#define kQ3ShaderTypeIllumination Q3_OBJECT_TYPE('i', 'l', 's', 'h')
#define kQ3IlluminationTypePhong Q3_OBJECT_TYPE('p', 'h', 'i', 'l')
#define kQ3IlluminationTypeLambert Q3_OBJECT_TYPE('l', 'm', 'i', 'l')
#define kQ3IlluminationTypeNULL Q3_OBJECT_TYPE('n', 'u', 'i', 'l')
#define kQ3ShapeTypeStyle Q3_OBJECT_TYPE('s', 't', 'y', 'l')
#define kQ3StyleTypeBackfacing Q3_OBJECT_TYPE('b', 'c', 'k', 'f')
#define kQ3StyleTypeInterpolation Q3_OBJECT_TYPE('i', 'n', 't', 'p')
#define kQ3StyleTypeFill Q3_OBJECT_TYPE('f', 'i', 's', 't')
#define kQ3StyleTypePickID Q3_OBJECT_TYPE('p', 'k', 'i', 'd')
#define kQ3StyleTypeReceiveShadows Q3_OBJECT_TYPE('r', 'c', 's', 'h')
#define kQ3StyleTypeHighlight Q3_OBJECT_TYPE('h', 'i', 'g', 'h')
#define kQ3StyleTypeSubdivision Q3_OBJECT_TYPE('s', 'b', 'd', 'v')
#define kQ3StyleTypeOrientation Q3_OBJECT_TYPE('o', 'f', 'd', 'r')
#define kQ3StyleTypePickParts Q3_OBJECT_TYPE('p', 'k', 'p', 't')
#define kQ3StyleTypeAntiAlias Q3_OBJECT_TYPE('a', 'n', 't', 'i')
#define kQ3StyleTypeFog Q3_OBJECT_TYPE('f', 'o', 'g', 'g')
#define kQ3ShapeTypeTransform Q3_OBJECT_TYPE('x', 'f', 'r', 'm')
#define kQ3TransformTypeMatrix Q3_OBJECT_TYPE('m', 't', 'r', 'x')
#define kQ3TransformTypeScale Q3_OBJECT_TYPE('s', 'c', 'a', 'l')
#define kQ3TransformTypeTranslate Q3_OBJECT_TYPE('t', 'r', 'n', 's')
#define kQ3TransformTypeRotate Q3_OBJECT_TYPE('r', 'o', 't', 't')
#define kQ3TransformTypeRotateAboutPoint Q3_OBJECT_TYPE('r', 't', 'a', 'p')
#define kQ3TransformTypeRotateAboutAxis Q3_OBJECT_TYPE('r', 't', 'a', 'a')
#define kQ3TransformTypeQuaternion Q3_OBJECT_TYPE('q', 't', 'r', 'n')
#define kQ3TransformTypeReset Q3_OBJECT_TYPE('r', 's', 'e', 't')
#define kQ3ShapeTypeLight Q3_OBJECT_TYPE('l', 'g', 'h', 't')
#define kQ3LightTypeAmbient Q3_OBJECT_TYPE('a', 'm', 'b', 'n')
#define kQ3LightTypeDirectional Q3_OBJECT_TYPE('d', 'r', 'c', 't')
#define kQ3LightTypePoint Q3_OBJECT_TYPE('p', 'n', 't', 'l')
#define kQ3LightTypeSpot Q3_OBJECT_TYPE('s', 'p', 'o', 't')
#define kQ3ShapeTypeCamera Q3_OBJECT_TYPE('c', 'm', 'r', 'a')
#define kQ3CameraTypeOrthographic Q3_OBJECT_TYPE('o', 'r', 't', 'h')
#define kQ3CameraTypeViewPlane Q3_OBJECT_TYPE('v', 'w', 'p', 'l')
#define kQ3CameraTypeViewAngleAspect Q3_OBJECT_TYPE('v', 'a', 'n', 'a')
#define kQ3ShapeTypeStateOperator Q3_OBJECT_TYPE('s', 't', 'o', 'p')
#define kQ3StateOperatorTypePush Q3_OBJECT_TYPE('p', 'u', 's', 'h')
#define kQ3StateOperatorTypePop Q3_OBJECT_TYPE('p', 'o', 'p', ' ')
#define kQ3ShapeTypeGroup Q3_OBJECT_TYPE('g', 'r', 'u', 'p')
#define kQ3GroupTypeDisplay Q3_OBJECT_TYPE('d', 's', 'p', 'g')
#define kQ3DisplayGroupTypeOrdered Q3_OBJECT_TYPE('o', 'r', 'd', 'g')
#define kQ3DisplayGroupTypeIOProxy Q3_OBJECT_TYPE('i', 'o', 'p', 'x')
#define kQ3GroupTypeLight Q3_OBJECT_TYPE('l', 'g', 'h', 'g')
#define kQ3GroupTypeInfo Q3_OBJECT_TYPE('i', 'n', 'f', 'o')
#define kQ3ShapeTypeUnknown Q3_OBJECT_TYPE('u', 'n', 'k', 'n')
#define kQ3UnknownTypeText Q3_OBJECT_TYPE('u', 'k', 't', 'x')
#define kQ3UnknownTypeBinary Q3_OBJECT_TYPE('u', 'k', 'b', 'n')
#define kQ3ShapeTypeReference Q3_OBJECT_TYPE('r', 'f', 'r', 'n')
#define kQ3ReferenceTypeExternal Q3_OBJECT_TYPE('r', 'f', 'e', 'x')
#define kQ3SharedTypeSet Q3_OBJECT_TYPE('s', 'e', 't', ' ')
#define kQ3SetTypeAttribute Q3_OBJECT_TYPE('a', 't', 't', 'r')
#define kQ3SharedTypeDrawContext Q3_OBJECT_TYPE('d', 'c', 't', 'x')
#define kQ3DrawContextTypePixmap Q3_OBJECT_TYPE('d', 'p', 'x', 'p')
#define kQ3DrawContextTypeMacintosh Q3_OBJECT_TYPE('d', 'm', 'a', 'c')
#define kQ3DrawContextTypeWin32DC Q3_OBJECT_TYPE('d', 'w', '3', '2')
#define kQ3DrawContextTypeDDSurface Q3_OBJECT_TYPE('d', 'd', 'd', 's')
#define kQ3DrawContextTypeX11 Q3_OBJECT_TYPE('d', 'x', '1', '1')
#define kQ3SharedTypeTexture Q3_OBJECT_TYPE('t', 'x', 't', 'r')
#define kQ3TextureTypePixmap Q3_OBJECT_TYPE('t', 'x', 'p', 'm')
#define kQ3TextureTypeMipmap Q3_OBJECT_TYPE('t', 'x', 'm', 'm')
#define kQ3TextureTypeCompressedPixmap Q3_OBJECT_TYPE('t', 'x', 'c', 'p')
#define kQ3SharedTypeFile Q3_OBJECT_TYPE('f', 'i', 'l', 'e')
#define kQ3SharedTypeStorage Q3_OBJECT_TYPE('s', 't', 'r', 'g')
#define kQ3StorageTypeMemory Q3_OBJECT_TYPE('m', 'e', 'm', 's')
#define kQ3MemoryStorageTypeHandle Q3_OBJECT_TYPE('h', 'n', 'd', 'l')
#define kQ3StorageTypeUnix Q3_OBJECT_TYPE('u', 'x', 's', 't')
#define kQ3UnixStorageTypePath Q3_OBJECT_TYPE('u', 'n', 'i', 'x')
#define kQ3StorageTypeMacintosh Q3_OBJECT_TYPE('m', 'a', 'c', 'n')
#define kQ3MacintoshStorageTypeFSSpec Q3_OBJECT_TYPE('m', 'a', 'c', 'p')
#define kQ3StorageTypeWin32 Q3_OBJECT_TYPE('w', 'i', 's', 't')
#define kQ3SharedTypeString Q3_OBJECT_TYPE('s', 't', 'r', 'n')
#define kQ3StringTypeCString Q3_OBJECT_TYPE('s', 't', 'r', 'c')
#define kQ3SharedTypeShapePart Q3_OBJECT_TYPE('s', 'p', 'r', 't')
#define kQ3ShapePartTypeMeshPart Q3_OBJECT_TYPE('s', 'p', 'm', 'h')
#define kQ3MeshPartTypeMeshFacePart Q3_OBJECT_TYPE('m', 'f', 'a', 'c')
#define kQ3MeshPartTypeMeshEdgePart Q3_OBJECT_TYPE('m', 'e', 'd', 'g')
#define kQ3MeshPartTypeMeshVertexPart Q3_OBJECT_TYPE('m', 'v', 't', 'x')
#define kQ3SharedTypeControllerState Q3_OBJECT_TYPE('c', 't', 's', 't')
#define kQ3SharedTypeTracker Q3_OBJECT_TYPE('t', 'r', 'k', 'r')
#define kQ3SharedTypeViewHints Q3_OBJECT_TYPE('v', 'w', 'h', 'n')
#define kQ3SharedTypeEndGroup Q3_OBJECT_TYPE('e', 'n', 'd', 'g')

/* ---- System ------------------------------------------------------------- */

/*
 * Q3Initialize: starts Q3. Calls nest: each successful call must be matched by
 * Q3Exit. Every other call except the error-manager calls fails with
 * kQ3ErrorNotInitialized until Q3 is initialized.
 * Errors: none. A nested call posts kQ3NoticeSystemAlreadyInitialized.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Initialize(void);

/*
 * Q3Exit: undoes one Q3Initialize. The last one shuts Q3 down; objects still
 * alive then are reported with kQ3WarningPossibleMemoryLeak (see
 * Q3Memory_CountLiveObjects) and stay valid should Q3 be initialized again.
 * Errors: kQ3ErrorNotInitialized when Q3 is not initialized.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Exit(void);

/* Q3IsInitialized: kQ3True between Q3Initialize and the matching Q3Exit. */
Q3_EXTERN_API_C(TQ3Boolean) Q3IsInitialized(void);

/*
 * Q3GetVersion: the QuickDraw 3D API version Q3 implements (1.6).
 * Errors: kQ3ErrorNULLParameter when either pointer is NULL.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GetVersion(unsigned long *majorRevision, unsigned long *minorRevision);

/**
 * Reports the release of QuickDraw 3D that Q3 implements, in the format of
 * the first four bytes of a Mac 'vers' resource: 0x01608000, release 1.6.0
 * final (major 0x01, minor and bug-fix 0x60, stage 0x80 final, build 0x00).
 *
 * @param releaseRevision  receives the release version.
 * @return kQ3Success, or kQ3Failure with *releaseRevision unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   releaseRevision is NULL.
 *
 * Ownership: none.
 */
Q3_EXTERN_API_C(TQ3Status) Q3GetReleaseVersion(unsigned long *releaseRevision);

/* ---- Object hierarchy ----------------------------------------------------- */

/*
 * The class hierarchy queries. Every class Q3 provides is registered; its
 * type is its kQ3...Type constant and its name is its 3D Metafile text name
 * where the class has one ("Box", "TriMesh", "AttributeSet", ...), else its
 * description in one word ("InteractiveRenderer", "WireframeRenderer",
 * "PixmapDrawContext", ...). Names compare exactly, case included. The root
 * of the hierarchy (kQ3ObjectTypeInvalid) is not a class.
 */

/**
 * Finds the type of the class with a name.
 *
 * @param objectClassString  the class name, '\0' terminated.
 * @param objectClassType    receives the class type.
 * @return kQ3Success, or kQ3Failure with *objectClassType unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     objectClassString or objectClassType is NULL.
 *   kQ3ErrorInvalidParameter  no class has that name.
 *
 * Ownership: none.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ObjectHierarchy_GetTypeFromString(TQ3ObjectClassNameString objectClassString,
                                                               TQ3ObjectType *objectClassType);

/**
 * Writes the name of a registered class.
 *
 * @param objectClassType    the class type.
 * @param objectClassString  receives the name, '\0' terminated (at most
 *                           kQ3StringMaximumLength bytes with the '\0').
 * @return kQ3Success, or kQ3Failure with objectClassString unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     objectClassString is NULL.
 *   kQ3ErrorInvalidParameter  no class has type objectClassType.
 *
 * Ownership: none.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ObjectHierarchy_GetStringFromType(TQ3ObjectType objectClassType,
                                                               TQ3ObjectClassNameString objectClassString);

/**
 * Reports whether a class with this type is registered.
 *
 * @param objectClassType  the class type.
 * @return kQ3True or kQ3False (kQ3False on failure).
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *
 * Ownership: none.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3ObjectHierarchy_IsTypeRegistered(TQ3ObjectType objectClassType);

/**
 * Reports whether a class with this name is registered.
 *
 * @param objectClassName  the class name, '\0' terminated.
 * @return kQ3True or kQ3False (kQ3False on failure).
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   objectClassName is NULL.
 *
 * Ownership: none.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3ObjectHierarchy_IsNameRegistered(const char *objectClassName);

/* The subclasses of a class, as Q3ObjectHierarchy_GetSubClassData fills it. */
struct TQ3SubClassData {
    unsigned long numClasses;  /* the number of subclass types found */
    TQ3ObjectType *classTypes; /* the subclass types (NULL when none) */
};
typedef struct TQ3SubClassData TQ3SubClassData;

/**
 * Lists the classes immediately below a class in the hierarchy, in
 * ascending order of type code. Every Qut front end (Quesa's sample
 * framework) builds its renderer menu with this and kQ3SharedTypeRenderer.
 *
 * @param objectClassType  the parent class type (kQ3ObjectTypeShared,
 *                         kQ3SharedTypeRenderer, ...).
 * @param subClassData     receives the count and a new array of types.
 * @return kQ3Success, or kQ3Failure with *subClassData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     subClassData is NULL.
 *   kQ3ErrorInvalidParameter  no class has type objectClassType.
 *   kQ3ErrorOutOfMemory       the array could not be allocated.
 *
 * Ownership: the caller frees classTypes with
 * Q3ObjectHierarchy_EmptySubClassData.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ObjectHierarchy_GetSubClassData(TQ3ObjectType objectClassType,
                                                             TQ3SubClassData *subClassData);

/**
 * Frees the array Q3ObjectHierarchy_GetSubClassData allocated, and sets
 * numClasses to 0 and classTypes to NULL. Emptying an empty one is harmless.
 *
 * @param subClassData  the data to empty.
 * @return kQ3Success, or kQ3Failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized  Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter   subClassData is NULL.
 *
 * Ownership: consumes subClassData->classTypes.
 */
Q3_EXTERN_API_C(TQ3Status) Q3ObjectHierarchy_EmptySubClassData(TQ3SubClassData *subClassData);

/*
 * Q3Memory_CountLiveObjects (Q3 extension): the number of Q3 objects (views,
 * shared objects) created and not yet disposed, across all threads. Tests use
 * it to prove that nothing leaks. Works whether or not Q3 is initialized.
 */
Q3_EXTERN_API_C(unsigned long) Q3Memory_CountLiveObjects(void);

/* ---- Objects ------------------------------------------------------------ */

/*
 * Q3Object_Dispose: releases the caller's reference. A shared object is
 * destroyed when its last reference goes; a view at once.
 * Errors: kQ3ErrorNULLParameter for NULL; kQ3ErrorInvalidObject for a handle
 * that is not a live Q3 object (already disposed, or never one).
 * Ownership: consumes one reference.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Object_Dispose(TQ3Object object);

/*
 * Q3Object_Duplicate: a deep, independent copy (an attribute set held by a
 * geometry is duplicated too). Views cannot be duplicated.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject;
 * kQ3ErrorInvalidObjectType for a view.
 * Ownership: the caller holds the one reference of the new object.
 */
Q3_EXTERN_API_C(TQ3Object) Q3Object_Duplicate(TQ3Object object);

/*
 * Q3Object_Submit: submits a drawable object (geometry, style, transform,
 * attribute set) to a view inside a rendering or bounding loop.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject; kQ3ErrorInvalidObjectType
 * when object is not drawable or view is not a view; kQ3ErrorViewNotStarted
 * outside a loop.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Object_Submit(TQ3Object object, TQ3ViewObject view);

/* Q3Object_IsDrawable: kQ3True when object may be submitted to a view.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject (then kQ3False). */
Q3_EXTERN_API_C(TQ3Boolean) Q3Object_IsDrawable(TQ3Object object);

/**
 * Reports whether an object can be written to a 3D Metafile: kQ3True for
 * every class Q3's 3DMF writer knows (geometries, groups, styles,
 * transforms, attribute sets, shaders, textures, cameras, lights, view
 * hints, strings, unknown objects), kQ3False for the rest (views, draw
 * contexts, renderers, storage, files, picks).
 *
 * @param object   the object to ask about.
 * @param theFile  the file it would be written to; any file object, open or
 *                 not (the answer does not depend on it).
 * @return kQ3True or kQ3False (kQ3False on failure).
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      object or theFile is NULL.
 *   kQ3ErrorInvalidObject      object or theFile is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  theFile is not a file.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Boolean) Q3Object_IsWritable(TQ3Object object, TQ3FileObject theFile);

/* Q3Object_GetType: the object's first-level type: kQ3ObjectTypeShared,
 * kQ3ObjectTypeView, ... Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject
 * (then kQ3ObjectTypeInvalid). */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Object_GetType(TQ3Object object);

/* Q3Object_GetLeafType: the object's most derived type, e.g.
 * kQ3GeometryTypeNURBCurve. Errors: as Q3Object_GetType. */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Object_GetLeafType(TQ3Object object);

/* Q3Object_IsType: kQ3True when object is of type theType or of a subclass.
 * Errors: as Q3Object_GetType (then kQ3False). */
Q3_EXTERN_API_C(TQ3Boolean) Q3Object_IsType(TQ3Object object, TQ3ObjectType theType);

/* ---- Shared objects ------------------------------------------------------ */

/* Q3Shared_GetType: the shared object's second-level type, e.g.
 * kQ3SharedTypeShape. Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (then kQ3ObjectTypeInvalid). */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Shared_GetType(TQ3SharedObject sharedObject);

/*
 * Q3Shared_GetReference: adds a reference and returns the same object.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject, kQ3ErrorInvalidObjectType
 * (not a shared object). Ownership: the caller holds one more reference and
 * must dispose it.
 */
Q3_EXTERN_API_C(TQ3SharedObject) Q3Shared_GetReference(TQ3SharedObject sharedObject);

/* Q3Shared_IsReferenced: kQ3True when more than one reference is held.
 * Errors: as Q3Shared_GetReference (then kQ3False). */
Q3_EXTERN_API_C(TQ3Boolean) Q3Shared_IsReferenced(TQ3SharedObject sharedObject);

/* Q3Shared_GetEditIndex: a serial number that changes with every edit of the
 * object; 0 on error. Errors: as Q3Shared_GetReference. */
Q3_EXTERN_API_C(unsigned long) Q3Shared_GetEditIndex(TQ3SharedObject sharedObject);

/* Q3Shared_Edited: bumps the edit index (and drops derived caches).
 * Errors: as Q3Shared_GetReference. */
Q3_EXTERN_API_C(TQ3Status) Q3Shared_Edited(TQ3SharedObject sharedObject);

/* Q3Shape_GetType: a shape's third-level type, e.g. kQ3ShapeTypeGeometry.
 * Errors: kQ3ErrorNULLParameter, kQ3ErrorInvalidObject,
 * kQ3ErrorInvalidObjectType (then kQ3ObjectTypeInvalid). */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Shape_GetType(TQ3ShapeObject shape);

/* ---- Bitmaps ------------------------------------------------------------- */

/*
 * Q3Bitmap_Empty: frees the bits of a bitmap Q3 filled (Q3Marker_GetBitmap,
 * Q3Marker_GetData) and sets image to NULL; a bitmap whose image is already
 * NULL is left alone. Errors: kQ3ErrorNULLParameter (bitmap is NULL).
 * Ownership: consumes the bits.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Bitmap_Empty(TQ3Bitmap *bitmap);

/*
 * Q3Bitmap_GetImageSize: the bytes a bitmap of width x height pixels needs
 * with rows packed to whole bytes: ((width + 7) / 8) * height (0 when that
 * does not fit an unsigned long). Errors: none besides kQ3ErrorNotInitialized
 * (then 0).
 */
Q3_EXTERN_API_C(unsigned long) Q3Bitmap_GetImageSize(unsigned long width, unsigned long height);

/* ---- Object system types (Apple's QD3D.h) ---------------------------------
 *
 * The class handle and metahandler of QD3DExtension.h and QD3DSet.h's
 * custom classes. A metahandler is called with each method type a class may
 * have and returns the method (or NULL); Q3 asks it only while the call that
 * was given it runs, as QuickDraw 3D promises.
 */
typedef struct OpaqueTQ3XObjectClass *TQ3XObjectClass;
typedef unsigned long TQ3XMethodType;

#define Q3_METHOD_TYPE(a, b, c, d) ((TQ3XMethodType)Q3_FOUR_CHARACTER_CONSTANT(a, b, c, d))

#define kQ3XMethodTypeObjectUnregister Q3_METHOD_TYPE('u', 'n', 'r', 'g')
/* Return (TQ3XFunctionPointer)kQ3True from the metahandler when objects of
 * the class may be submitted in a view's loop. */
#define kQ3XMethodTypeObjectIsDrawable Q3_METHOD_TYPE('i', 's', 'd', 'r')

typedef void (*TQ3XFunctionPointer)(void);
typedef TQ3XFunctionPointer (*TQ3XMetaHandler)(TQ3XMethodType methodType);
typedef TQ3Status (*TQ3XObjectUnregisterMethod)(TQ3XObjectClass objectClass);

/* ---- Elements of shapes --------------------------------------------------
 *
 * QuickDraw 3D 1.5's note: shapes and sets are polymorphic. Every
 * Q3Shape_...Element call takes a shape or a set as its first parameter and
 * on a set is the Q3Set_ call of the same meaning. A shape keeps its
 * elements itself (not in a set); the element type kQ3ElementTypeSet is a
 * set attached to the shape, what Q3Shape_GetSet and Q3Shape_SetSet read and
 * replace. The element types are those a set takes (QD3DSet.h): the
 * attribute types, registered custom element and attribute classes, and
 * kQ3ElementTypeSet (a TQ3SetObject, held by reference: Add retains it, Get
 * returns a new reference).
 *
 * Errors shared by these calls, in the order checked:
 * kQ3ErrorNULLParameter / kQ3ErrorInvalidObject (the shape),
 * kQ3ErrorInvalidObjectType (neither a shape nor a set),
 * kQ3ErrorUnknownElementType (a type no element class has),
 * kQ3ErrorNULLParameter (data), then the element's own errors as Q3Set_Add
 * and Q3Set_Get list them; kQ3ErrorAttributeNotContained when Get or Clear
 * find no element of the type. A failed call changes nothing.
 */

/* Q3Shape_GetSet: *theSet = a new reference to the set attached to the
 * shape, or NULL when it has none (then kQ3Success). Errors: as above;
 * kQ3ErrorNULLParameter (theSet). Ownership: the caller disposes the set. */
Q3_EXTERN_API_C(TQ3Status) Q3Shape_GetSet(TQ3ShapeObject shape, TQ3SetObject *theSet);

/* Q3Shape_SetSet: attaches theSet to the shape (NULL removes the set); the
 * shape holds a reference. Errors: as above; kQ3ErrorInvalidObjectType
 * (theSet is no set). */
Q3_EXTERN_API_C(TQ3Status) Q3Shape_SetSet(TQ3ShapeObject shape, TQ3SetObject theSet);

/* Q3Shape_AddElement: copies *data into the shape's element theType,
 * replacing one of that type. */
Q3_EXTERN_API_C(TQ3Status) Q3Shape_AddElement(TQ3ShapeObject shape, TQ3ElementType theType, const void *data);

/* Q3Shape_GetElement: copies the shape's element theType to *data. */
Q3_EXTERN_API_C(TQ3Status) Q3Shape_GetElement(TQ3ShapeObject shape, TQ3ElementType theType, void *data);

/* Q3Shape_ContainsElement: kQ3True when the shape has an element theType
 * (kQ3False on error). */
Q3_EXTERN_API_C(TQ3Boolean) Q3Shape_ContainsElement(TQ3ShapeObject shape, TQ3ElementType theType);

/* Q3Shape_GetNextElementType: the walk over the shape's element types:
 * kQ3ElementTypeNone starts it and is returned after the last type; the
 * attached set, if any, comes last as kQ3ElementTypeSet. Errors: as above;
 * kQ3ErrorNULLParameter (theType). */
Q3_EXTERN_API_C(TQ3Status) Q3Shape_GetNextElementType(TQ3ShapeObject shape, TQ3ElementType *theType);

/* Q3Shape_EmptyElements: removes every element of the shape, the attached
 * set included. */
Q3_EXTERN_API_C(TQ3Status) Q3Shape_EmptyElements(TQ3ShapeObject shape);

/* Q3Shape_ClearElement: removes the shape's element theType. */
Q3_EXTERN_API_C(TQ3Status) Q3Shape_ClearElement(TQ3ShapeObject shape, TQ3ElementType theType);

/* ---- Elements of any object (Quesa extension) -----------------------------
 *
 * Quesa's Q3Object_ element calls, for ports that moved from Quesa: on a
 * set they are the Q3Set_ calls, on a shape the Q3Shape_ calls, and any
 * other object (a view, a storage object, ...) keeps its elements as a
 * shape does. Errors and ownership: as the Q3Shape_ calls (any live object
 * is accepted).
 */
Q3_EXTERN_API_C(TQ3Status) Q3Object_AddElement(TQ3Object object, TQ3ElementType theType, const void *data);
Q3_EXTERN_API_C(TQ3Status) Q3Object_GetElement(TQ3Object object, TQ3ElementType theType, void *data);
Q3_EXTERN_API_C(TQ3Boolean) Q3Object_ContainsElement(TQ3Object object, TQ3ElementType theType);
Q3_EXTERN_API_C(TQ3Status) Q3Object_GetNextElementType(TQ3Object object, TQ3ElementType *theType);
Q3_EXTERN_API_C(TQ3Status) Q3Object_EmptyElements(TQ3Object object);
Q3_EXTERN_API_C(TQ3Status) Q3Object_ClearElement(TQ3Object object, TQ3ElementType theType);

#ifdef __cplusplus
}
#endif

#endif /* QD3D_H */
