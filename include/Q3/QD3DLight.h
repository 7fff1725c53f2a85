/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#ifndef QD3DLIGHT_H
#define QD3DLIGHT_H

/*
 * Lights: ambient, directional, point and spot lights, as QuickDraw 3D 1.6
 * declares them. A view is lit by the lights of its light group
 * (Q3View_SetLightGroup, QD3DView.h; Q3LightGroup_New, QD3DGroup.h); lights
 * are not submitted like other shapes. Locations and directions are in world
 * coordinates.
 *
 * Error conventions shared by every function in this header: a call that
 * fails posts exactly one error and leaves every object and output it was
 * given unchanged. "Not a live Q3 object" means a handle that was disposed
 * or never came from Q3. The checks run in this order, and the first that
 * fails decides the error: Q3 is initialized; then the arguments from left
 * to right (a handle: not NULL, a live Q3 object, of the right class; a
 * pointer: not NULL); then the function's other conditions in the order it
 * lists them (for a data structure, the rules given with its type, in their
 * order). Every successful setter changes the light's edit index
 * (Q3Shared_GetEditIndex); a failed one leaves it unchanged.
 *
 * The rules of the data structures below are checked by _New, _SetData and
 * every single-value setter alike: a setter checks the light's whole data
 * with its value replaced. A broken rule fails with
 * kQ3ErrorInvalidParameter. A TQ3Boolean is never an error: any value
 * other than kQ3False is taken, and stored, as kQ3True (legacy code passes
 * plain nonzero ints), as in QD3DDrawContext.h.
 */

#include "QD3D.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * How a point or spot light weakens with the distance d from it: not at
 * all, as 1 / d, or as 1 / d^2.
 */
enum TQ3AttenuationType {
    kQ3AttenuationTypeNone = 0,
    kQ3AttenuationTypeInverseDistance = 1,
    kQ3AttenuationTypeInverseDistanceSquared = 2
};
typedef enum TQ3AttenuationType TQ3AttenuationType;

/*
 * How a spot light's intensity falls from full at the hot angle to nothing
 * at the outer angle: at once (none), linearly, exponentially, or along a
 * cosine curve.
 */
enum TQ3FallOffType {
    kQ3FallOffTypeNone = 0,
    kQ3FallOffTypeLinear = 1,
    kQ3FallOffTypeExponential = 2,
    kQ3FallOffTypeCosine = 3
};
typedef enum TQ3FallOffType TQ3FallOffType;

/*
 * What every light has: on or off, a brightness and a colour. Rules:
 *   brightness  finite. 0 to 1 is the usual range; as the QD3D book allows,
 *               Q3 also takes brighter than full (above 1) and negative
 *               lights, and keeps them as given for the renderer.
 *   color       every component finite (not clamped).
 */
struct TQ3LightData {
    TQ3Boolean isOn;
    float brightness;
    TQ3ColorRGB color;
};
typedef struct TQ3LightData TQ3LightData;

/*
 * A light travelling in one direction everywhere, as from a distant source.
 * Rules: lightData's; direction finite and not the zero vector (its length
 * does not matter, and it is returned as given).
 */
struct TQ3DirectionalLightData {
    TQ3LightData lightData;
    TQ3Boolean castsShadows;
    TQ3Vector3D direction;
};
typedef struct TQ3DirectionalLightData TQ3DirectionalLightData;

/*
 * A light radiating from one location in every direction. Rules:
 * lightData's; attenuation a TQ3AttenuationType value; location finite.
 */
struct TQ3PointLightData {
    TQ3LightData lightData;
    TQ3Boolean castsShadows;
    TQ3AttenuationType attenuation;
    TQ3Point3D location;
};
typedef struct TQ3PointLightData TQ3PointLightData;

/*
 * A cone of light from one location along a direction. hotAngle is the
 * half-angle, in radians, within which the light has full intensity;
 * outerAngle the half-angle beyond which it has none; fallOff how it falls
 * in between. Rules, in this order: lightData's; attenuation a
 * TQ3AttenuationType value; location finite; direction finite and not the
 * zero vector; hotAngle finite and within 0..kQ3PiOver2 (QD3DMath.h, the
 * float pi / 2); outerAngle finite and within 0..kQ3PiOver2; outerAngle not
 * less than hotAngle; fallOff a TQ3FallOffType value. So to widen a cone
 * with the single setters, set the outer angle first; to narrow it, the hot
 * angle first.
 */
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

/* ---- Every light --------------------------------------------------------- */

/**
 * Returns the kind of a light.
 *
 * @param light  any light.
 * @return kQ3LightTypeAmbient, kQ3LightTypeDirectional, kQ3LightTypePoint or
 *         kQ3LightTypeSpot, or kQ3ObjectTypeInvalid on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3ObjectType) Q3Light_GetType(TQ3LightObject light);

/**
 * Reads whether a light is on.
 *
 * @param light  the light to read.
 * @param isOn   receives kQ3True if the light is on.
 * @return kQ3Success, or kQ3Failure with *isOn unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or isOn is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Light_GetState(TQ3LightObject light, TQ3Boolean *isOn);

/**
 * Reads the brightness of a light.
 *
 * @param light       the light to read.
 * @param brightness  receives the brightness.
 * @return kQ3Success, or kQ3Failure with *brightness unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or brightness is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Light_GetBrightness(TQ3LightObject light, float *brightness);

/**
 * Reads the colour of a light.
 *
 * @param light  the light to read.
 * @param color  receives the colour.
 * @return kQ3Success, or kQ3Failure with *color unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or color is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Light_GetColor(TQ3LightObject light, TQ3ColorRGB *color);

/**
 * Turns a light on or off, keeping its other values.
 *
 * @param light  the light to change.
 * @param isOn   kQ3True to turn the light on, kQ3False to turn it off; any
 *               nonzero value is stored as kQ3True.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Light_SetState(TQ3LightObject light, TQ3Boolean isOn);

/**
 * Changes the brightness of a light, keeping its other values; the light's
 * whole data is checked with the new value, as by SetData.
 *
 * @param light       the light to change.
 * @param brightness  the new brightness; any finite value (see TQ3LightData).
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a light.
 *   kQ3ErrorInvalidParameter   brightness is NaN or infinite.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Light_SetBrightness(TQ3LightObject light, float brightness);

/**
 * Changes the colour of a light, keeping its other values; the light's whole
 * data is checked with the new value, as by SetData.
 *
 * @param light  the light to change.
 * @param color  the new colour; finite components.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or color is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a light.
 *   kQ3ErrorInvalidParameter   a component of *color is NaN or infinite.
 *
 * Ownership: no references change; *color is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Light_SetColor(TQ3LightObject light, const TQ3ColorRGB *color);

/**
 * Reads the on state, brightness and colour (the data every light has) of a
 * light.
 *
 * @param light      the light to read.
 * @param lightData  receives the values.
 * @return kQ3Success, or kQ3Failure with *lightData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or lightData is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Light_GetData(TQ3LightObject light, TQ3LightData *lightData);

/**
 * Replaces the on state, brightness and colour (the data every light has) of
 * a light.
 *
 * @param light      the light to change.
 * @param lightData  the new values.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or lightData is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a light.
 *   kQ3ErrorInvalidParameter   lightData breaks a rule of TQ3LightData.
 *
 * Ownership: no references change; *lightData is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3Light_SetData(TQ3LightObject light, const TQ3LightData *lightData);

/* ---- Ambient light ------------------------------------------------------- */

/**
 * Creates an ambient light.
 *
 * @param lightData  the light's values.
 * @return the new light, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     lightData is NULL.
 *   kQ3ErrorInvalidParameter  lightData breaks a rule of TQ3LightData.
 *   kQ3ErrorOutOfMemory       the light cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new light is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3LightObject) Q3AmbientLight_New(const TQ3LightData *lightData);

/**
 * Reads the values of an ambient light.
 *
 * @param light      the light to read.
 * @param lightData  receives the values.
 * @return kQ3Success, or kQ3Failure with *lightData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or lightData is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not an ambient light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AmbientLight_GetData(TQ3LightObject light, TQ3LightData *lightData);

/**
 * Replaces the values of an ambient light.
 *
 * @param light      the light to change.
 * @param lightData  the new values.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or lightData is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not an ambient light.
 *   kQ3ErrorInvalidParameter   lightData breaks a rule of TQ3LightData.
 *
 * Ownership: no references change; *lightData is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3AmbientLight_SetData(TQ3LightObject light, const TQ3LightData *lightData);

/* ---- Directional light --------------------------------------------------- */

/**
 * Creates a directional light.
 *
 * @param directionalLightData  the light's values.
 * @return the new light, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     directionalLightData is NULL.
 *   kQ3ErrorInvalidParameter  directionalLightData breaks a rule of
 *                             TQ3DirectionalLightData.
 *   kQ3ErrorOutOfMemory       the light cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new light is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3LightObject) Q3DirectionalLight_New(const TQ3DirectionalLightData *directionalLightData);

/**
 * Reads whether a directional light casts shadows.
 *
 * @param light         the light to read.
 * @param castsShadows  receives kQ3True or kQ3False.
 * @return kQ3Success, or kQ3Failure with *castsShadows unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or castsShadows is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a directional light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DirectionalLight_GetCastShadowsState(TQ3LightObject light,
                                                                  TQ3Boolean *castsShadows);

/**
 * Reads the direction of a directional light.
 *
 * @param light      the light to read.
 * @param direction  receives the direction, as it was given.
 * @return kQ3Success, or kQ3Failure with *direction unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or direction is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a directional light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DirectionalLight_GetDirection(TQ3LightObject light, TQ3Vector3D *direction);

/**
 * Changes whether a directional light casts shadows, keeping its other
 * values.
 *
 * @param light         the light to change.
 * @param castsShadows  kQ3True if the light casts shadows; any nonzero value
 *                      is stored as kQ3True.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a directional light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DirectionalLight_SetCastShadowsState(TQ3LightObject light,
                                                                  TQ3Boolean castsShadows);

/**
 * Changes the direction of a directional light, keeping its other values; the
 * light's whole data is checked with the new value, as by SetData.
 *
 * @param light      the light to change.
 * @param direction  the new direction, in world coordinates, of any length
 *                   but zero.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or direction is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a directional light.
 *   kQ3ErrorInvalidParameter   a component of *direction is NaN or infinite,
 *                              or all three are zero.
 *
 * Ownership: no references change; *direction is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DirectionalLight_SetDirection(TQ3LightObject light,
                                                           const TQ3Vector3D *direction);

/**
 * Reads the values of a directional light.
 *
 * @param light                 the light to read.
 * @param directionalLightData  receives the values.
 * @return kQ3Success, or kQ3Failure with *directionalLightData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or directionalLightData is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a directional light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DirectionalLight_GetData(TQ3LightObject light,
                                                      TQ3DirectionalLightData *directionalLightData);

/**
 * Replaces the values of a directional light.
 *
 * @param light                 the light to change.
 * @param directionalLightData  the new values.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or directionalLightData is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a directional light.
 *   kQ3ErrorInvalidParameter   directionalLightData breaks a rule of
 *                              TQ3DirectionalLightData.
 *
 * Ownership: no references change; *directionalLightData is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3DirectionalLight_SetData(TQ3LightObject light,
                                                      const TQ3DirectionalLightData *directionalLightData);

/* ---- Point light --------------------------------------------------------- */

/**
 * Creates a point light.
 *
 * @param pointLightData  the light's values.
 * @return the new light, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     pointLightData is NULL.
 *   kQ3ErrorInvalidParameter  pointLightData breaks a rule of
 *                             TQ3PointLightData.
 *   kQ3ErrorOutOfMemory       the light cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new light is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3LightObject) Q3PointLight_New(const TQ3PointLightData *pointLightData);

/**
 * Reads whether a point light casts shadows.
 *
 * @param light         the light to read.
 * @param castsShadows  receives kQ3True or kQ3False.
 * @return kQ3Success, or kQ3Failure with *castsShadows unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or castsShadows is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a point light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PointLight_GetCastShadowsState(TQ3LightObject light, TQ3Boolean *castsShadows);

/**
 * Reads the attenuation of a point light.
 *
 * @param light        the light to read.
 * @param attenuation  receives the attenuation.
 * @return kQ3Success, or kQ3Failure with *attenuation unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or attenuation is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a point light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PointLight_GetAttenuation(TQ3LightObject light, TQ3AttenuationType *attenuation);

/**
 * Reads the location of a point light.
 *
 * @param light     the light to read.
 * @param location  receives the location.
 * @return kQ3Success, or kQ3Failure with *location unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or location is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a point light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PointLight_GetLocation(TQ3LightObject light, TQ3Point3D *location);

/**
 * Reads the values of a point light.
 *
 * @param light           the light to read.
 * @param pointLightData  receives the values.
 * @return kQ3Success, or kQ3Failure with *pointLightData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or pointLightData is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a point light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PointLight_GetData(TQ3LightObject light, TQ3PointLightData *pointLightData);

/**
 * Changes whether a point light casts shadows, keeping its other
 * values.
 *
 * @param light         the light to change.
 * @param castsShadows  kQ3True if the light casts shadows; any nonzero value
 *                      is stored as kQ3True.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a point light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PointLight_SetCastShadowsState(TQ3LightObject light, TQ3Boolean castsShadows);

/**
 * Changes the attenuation of a point light, keeping its other values; the
 * light's whole data is checked with the new value, as by SetData.
 *
 * @param light        the light to change.
 * @param attenuation  kQ3AttenuationTypeNone,
 *                     kQ3AttenuationTypeInverseDistance or
 *                     kQ3AttenuationTypeInverseDistanceSquared.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a point light.
 *   kQ3ErrorInvalidParameter   attenuation is not a TQ3AttenuationType value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PointLight_SetAttenuation(TQ3LightObject light, TQ3AttenuationType attenuation);

/**
 * Changes the location of a point light, keeping its other values; the
 * light's whole data is checked with the new value, as by SetData.
 *
 * @param light     the light to change.
 * @param location  the new location, in world coordinates.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or location is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a point light.
 *   kQ3ErrorInvalidParameter   a component of *location is NaN or infinite.
 *
 * Ownership: no references change; *location is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PointLight_SetLocation(TQ3LightObject light, const TQ3Point3D *location);

/**
 * Replaces the values of a point light.
 *
 * @param light           the light to change.
 * @param pointLightData  the new values.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or pointLightData is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a point light.
 *   kQ3ErrorInvalidParameter   pointLightData breaks a rule of
 *                              TQ3PointLightData.
 *
 * Ownership: no references change; *pointLightData is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3PointLight_SetData(TQ3LightObject light,
                                                const TQ3PointLightData *pointLightData);

/* ---- Spot light ---------------------------------------------------------- */

/**
 * Creates a spot light.
 *
 * @param spotLightData  the light's values.
 * @return the new light, or NULL on failure.
 *
 * Errors:
 *   kQ3ErrorNotInitialized    Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter     spotLightData is NULL.
 *   kQ3ErrorInvalidParameter  spotLightData breaks a rule of
 *                             TQ3SpotLightData.
 *   kQ3ErrorOutOfMemory       the light cannot be allocated.
 *
 * Ownership: the caller owns the one reference the new light is born with and
 * releases it with Q3Object_Dispose.
 */
Q3_EXTERN_API_C(TQ3LightObject) Q3SpotLight_New(const TQ3SpotLightData *spotLightData);

/**
 * Reads whether a spot light casts shadows.
 *
 * @param light         the light to read.
 * @param castsShadows  receives kQ3True or kQ3False.
 * @return kQ3Success, or kQ3Failure with *castsShadows unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or castsShadows is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_GetCastShadowsState(TQ3LightObject light, TQ3Boolean *castsShadows);

/**
 * Reads the attenuation of a spot light.
 *
 * @param light        the light to read.
 * @param attenuation  receives the attenuation.
 * @return kQ3Success, or kQ3Failure with *attenuation unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or attenuation is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_GetAttenuation(TQ3LightObject light, TQ3AttenuationType *attenuation);

/**
 * Reads the location of a spot light.
 *
 * @param light     the light to read.
 * @param location  receives the location.
 * @return kQ3Success, or kQ3Failure with *location unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or location is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_GetLocation(TQ3LightObject light, TQ3Point3D *location);

/**
 * Reads the direction of a spot light.
 *
 * @param light      the light to read.
 * @param direction  receives the direction, as it was given.
 * @return kQ3Success, or kQ3Failure with *direction unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or direction is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_GetDirection(TQ3LightObject light, TQ3Vector3D *direction);

/**
 * Reads the hot angle of a spot light.
 *
 * @param light     the light to read.
 * @param hotAngle  receives the hot angle, in radians.
 * @return kQ3Success, or kQ3Failure with *hotAngle unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or hotAngle is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_GetHotAngle(TQ3LightObject light, float *hotAngle);

/**
 * Reads the outer angle of a spot light.
 *
 * @param light       the light to read.
 * @param outerAngle  receives the outer angle, in radians.
 * @return kQ3Success, or kQ3Failure with *outerAngle unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or outerAngle is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_GetOuterAngle(TQ3LightObject light, float *outerAngle);

/**
 * Reads the fall-off of a spot light.
 *
 * @param light    the light to read.
 * @param fallOff  receives the fall-off.
 * @return kQ3Success, or kQ3Failure with *fallOff unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or fallOff is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_GetFallOff(TQ3LightObject light, TQ3FallOffType *fallOff);

/**
 * Reads the values of a spot light.
 *
 * @param light          the light to read.
 * @param spotLightData  receives the values.
 * @return kQ3Success, or kQ3Failure with *spotLightData unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or spotLightData is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_GetData(TQ3LightObject light, TQ3SpotLightData *spotLightData);

/**
 * Changes whether a spot light casts shadows, keeping its other values.
 *
 * @param light         the light to change.
 * @param castsShadows  kQ3True if the light casts shadows; any nonzero value
 *                      is stored as kQ3True.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_SetCastShadowsState(TQ3LightObject light, TQ3Boolean castsShadows);

/**
 * Changes the attenuation of a spot light, keeping its other values; the
 * light's whole data is checked with the new value, as by SetData.
 *
 * @param light        the light to change.
 * @param attenuation  kQ3AttenuationTypeNone,
 *                     kQ3AttenuationTypeInverseDistance or
 *                     kQ3AttenuationTypeInverseDistanceSquared.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *   kQ3ErrorInvalidParameter   attenuation is not a TQ3AttenuationType value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_SetAttenuation(TQ3LightObject light, TQ3AttenuationType attenuation);

/**
 * Changes the location of a spot light, keeping its other values; the light's
 * whole data is checked with the new value, as by SetData.
 *
 * @param light     the light to change.
 * @param location  the new location, in world coordinates.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or location is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *   kQ3ErrorInvalidParameter   a component of *location is NaN or infinite.
 *
 * Ownership: no references change; *location is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_SetLocation(TQ3LightObject light, const TQ3Point3D *location);

/**
 * Changes the direction of a spot light, keeping its other values; the
 * light's whole data is checked with the new value, as by SetData.
 *
 * @param light      the light to change.
 * @param direction  the new direction, in world coordinates, of any length
 *                   but zero.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or direction is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *   kQ3ErrorInvalidParameter   a component of *direction is NaN or infinite,
 *                              or all three are zero.
 *
 * Ownership: no references change; *direction is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_SetDirection(TQ3LightObject light, const TQ3Vector3D *direction);

/**
 * Changes the hot angle of a spot light, keeping its other values; the
 * light's whole data is checked with the new value, as by SetData.
 *
 * @param light     the light to change.
 * @param hotAngle  the new half-angle of full intensity, in radians, from 0
 *                  to the outer angle.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *   kQ3ErrorInvalidParameter   hotAngle is NaN or infinite, outside
 *                              0..kQ3PiOver2, or greater than the outer
 *                              angle.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_SetHotAngle(TQ3LightObject light, float hotAngle);

/**
 * Changes the outer angle of a spot light, keeping its other values; the
 * light's whole data is checked with the new value, as by SetData.
 *
 * @param light       the light to change.
 * @param outerAngle  the new half-angle of the cone, in radians, from the hot
 *                    angle to kQ3PiOver2.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *   kQ3ErrorInvalidParameter   outerAngle is NaN or infinite, outside
 *                              0..kQ3PiOver2, or less than the hot angle.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_SetOuterAngle(TQ3LightObject light, float outerAngle);

/**
 * Changes the fall-off of a spot light, keeping its other values; the light's
 * whole data is checked with the new value, as by SetData.
 *
 * @param light    the light to change.
 * @param fallOff  kQ3FallOffTypeNone, kQ3FallOffTypeLinear,
 *                 kQ3FallOffTypeExponential or kQ3FallOffTypeCosine.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *   kQ3ErrorInvalidParameter   fallOff is not a TQ3FallOffType value.
 *
 * Ownership: no references change.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_SetFallOff(TQ3LightObject light, TQ3FallOffType fallOff);

/**
 * Replaces the values of a spot light.
 *
 * @param light          the light to change.
 * @param spotLightData  the new values.
 * @return kQ3Success, or kQ3Failure with the light unchanged.
 *
 * Errors:
 *   kQ3ErrorNotInitialized     Q3Initialize has not been called.
 *   kQ3ErrorNULLParameter      light or spotLightData is NULL.
 *   kQ3ErrorInvalidObject      light is not a live Q3 object.
 *   kQ3ErrorInvalidObjectType  light is not a spot light.
 *   kQ3ErrorInvalidParameter   spotLightData breaks a rule of
 *                              TQ3SpotLightData.
 *
 * Ownership: no references change; *spotLightData is copied.
 */
Q3_EXTERN_API_C(TQ3Status) Q3SpotLight_SetData(TQ3LightObject light, const TQ3SpotLightData *spotLightData);

#ifdef __cplusplus
}
#endif

#endif /* QD3DLIGHT_H */
