/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef QD3DACCELERATION_H
#define QD3DACCELERATION_H

/*
 * QD3DAcceleration.h: the RAVE vendor and engine identifiers of QuickDraw 3D
 * 1.6's "low-level 3D driver API" header, which is all that header declares.
 * Legacy code includes it to pass a vendor and engine to
 * Q3InteractiveRenderer_SetPreferences (QD3DRenderer.h); Q3 stores that
 * preference and draws with its own renderer whatever it says, because RAVE
 * (Apple's Mac-only rasterizer interface) does not exist on Linux. Values
 * are Apple's.
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The system chooses the "best" drawing engine: the default. */
enum { kQAVendor_BestChoice = -1 };

/* Vendors of drawing engines; with a vendor-defined engine ID they select
 * one engine. */
enum {
    kQAVendor_Apple = 0,
    kQAVendor_ATI = 1,
    kQAVendor_Radius = 2,
    kQAVendor_DesignMark = 3,
    kQAVendor_Matrox = 4,
    kQAVendor_Yarc = 5,
    kQAVendor_DiamondMM = 6,
    kQAVendor_3DLabs = 7,
    kQAVendor_D3DAdaptor = 8,
    kQAVendor_IXMicro = 9,
    kQAVendor_NumberNine = 10,
    kQAVendor_MicroConversions = 11,
    kQAVendor_PurpleShark = 12,
    kQAVendor_VillageTronic = 14
};

/* Apple's engines. */
enum {
    kQAEngine_AppleSW = 0,  /* default software rasterizer */
    kQAEngine_AppleHW = -1, /* Apple accelerator */
    kQAEngine_AppleHW2 = 1, /* another Apple accelerator */
    kQAEngine_AppleHW3 = 2  /* another Apple accelerator */
};

#ifdef __cplusplus
}
#endif

#endif /* QD3DACCELERATION_H */
