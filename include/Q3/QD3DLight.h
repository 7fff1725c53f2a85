/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef QD3DLIGHT_H
#define QD3DLIGHT_H

/*
 * Lights: ambient, directional, point and spot lights, as QuickDraw 3D 1.6
 * declares them. A view is lit by the lights of its light group
 * (Q3View_SetLightGroup, QD3DView.h; Q3LightGroup_New, QD3DGroup.h).
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

enum TQ3AttenuationType {
    kQ3AttenuationTypeNone = 0,
    kQ3AttenuationTypeInverseDistance = 1,
    kQ3AttenuationTypeInverseDistanceSquared = 2
};
typedef enum TQ3AttenuationType TQ3AttenuationType;

enum TQ3FallOffType {
    kQ3FallOffTypeNone = 0,
    kQ3FallOffTypeLinear = 1,
    kQ3FallOffTypeExponential = 2,
    kQ3FallOffTypeCosine = 3
};
typedef enum TQ3FallOffType TQ3FallOffType;

/* What every light has: on or off, a brightness and a colour. */
struct TQ3LightData {
    TQ3Boolean isOn;
    float brightness;
    TQ3ColorRGB color;
};
typedef struct TQ3LightData TQ3LightData;

struct TQ3DirectionalLightData {
    TQ3LightData lightData;
    TQ3Boolean castsShadows;
    TQ3Vector3D direction;
};
typedef struct TQ3DirectionalLightData TQ3DirectionalLightData;

struct TQ3PointLightData {
    TQ3LightData lightData;
    TQ3Boolean castsShadows;
    TQ3AttenuationType attenuation;
    TQ3Point3D location;
};
typedef struct TQ3PointLightData TQ3PointLightData;

struct TQ3SpotLightData {
    TQ3LightData lightData;
    TQ3Boolean castsShadows;
    TQ3AttenuationType attenuation;
    TQ3Point3D location;
    TQ3Vector3D direction;
    float hotAngle;
    float outerAngle;
    TQ3FallOffType fallOff;
};
typedef struct TQ3SpotLightData TQ3SpotLightData;

#ifdef __cplusplus
}
#endif

#endif /* QD3DLIGHT_H */
