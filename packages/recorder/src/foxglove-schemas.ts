/*
 * Foxglove's well-known message schemas, as JSON Schema, for the few we write. Named exactly as
 * Foxglove names them (foxglove.PoseInFrame, ...), so Foxglove and Lichtblick draw them with no
 * setup. Written out here rather than taken from @foxglove/schemas, which ships every schema in
 * every encoding for the sake of these four.
 */

/** Foxglove's `time`. */
export const time = {
  type: 'object',
  title: 'time',
  properties: {
    sec: { type: 'integer', minimum: 0 },
    nsec: { type: 'integer', minimum: 0, maximum: 999_999_999 },
  },
  required: ['sec', 'nsec'],
} as const;

/** foxglove.Vector3. */
export const vector3 = {
  type: 'object',
  title: 'foxglove.Vector3',
  properties: { x: { type: 'number' }, y: { type: 'number' }, z: { type: 'number' } },
  required: ['x', 'y', 'z'],
} as const;

/** foxglove.Quaternion. */
export const quaternion = {
  type: 'object',
  title: 'foxglove.Quaternion',
  properties: {
    x: { type: 'number' },
    y: { type: 'number' },
    z: { type: 'number' },
    w: { type: 'number' },
  },
  required: ['x', 'y', 'z', 'w'],
} as const;

/** foxglove.Pose. */
export const pose = {
  type: 'object',
  title: 'foxglove.Pose',
  properties: { position: vector3, orientation: quaternion },
  required: ['position', 'orientation'],
} as const;

/** A JSON Schema under the name a viewer knows it by. */
export interface NamedJsonSchema {
  readonly name: string;
  readonly schema: Readonly<Record<string, unknown>>;
}

export const POSE_IN_FRAME: NamedJsonSchema = {
  name: 'foxglove.PoseInFrame',
  schema: {
    title: 'foxglove.PoseInFrame',
    description: 'A timestamped pose for an object or reference frame in 3D space',
    type: 'object',
    properties: {
      timestamp: time,
      frame_id: { type: 'string' },
      pose,
    },
    required: ['timestamp', 'frame_id', 'pose'],
  },
};

export const FRAME_TRANSFORM: NamedJsonSchema = {
  name: 'foxglove.FrameTransform',
  schema: {
    title: 'foxglove.FrameTransform',
    description: 'A transform between two reference frames in 3D space',
    type: 'object',
    properties: {
      timestamp: time,
      parent_frame_id: { type: 'string' },
      child_frame_id: { type: 'string' },
      translation: vector3,
      rotation: quaternion,
    },
    required: ['timestamp', 'parent_frame_id', 'child_frame_id', 'translation', 'rotation'],
  },
};

export const COMPRESSED_IMAGE: NamedJsonSchema = {
  name: 'foxglove.CompressedImage',
  schema: {
    title: 'foxglove.CompressedImage',
    description: 'A compressed image',
    type: 'object',
    properties: {
      timestamp: time,
      frame_id: { type: 'string' },
      data: { type: 'string', contentEncoding: 'base64' },
      format: { type: 'string' },
    },
    required: ['timestamp', 'frame_id', 'data', 'format'],
  },
};

export const LOG: NamedJsonSchema = {
  name: 'foxglove.Log',
  schema: {
    title: 'foxglove.Log',
    description: 'A log message',
    type: 'object',
    properties: {
      timestamp: time,
      level: {
        type: 'integer',
        description: 'UNKNOWN 0, DEBUG 1, INFO 2, WARNING 3, ERROR 4, FATAL 5',
        enum: [0, 1, 2, 3, 4, 5],
      },
      message: { type: 'string' },
      name: { type: 'string' },
      file: { type: 'string' },
      line: { type: 'integer', minimum: 0 },
    },
    required: ['timestamp', 'level', 'message', 'name', 'file', 'line'],
  },
};

/** Foxglove's log levels by our level names. */
export const FOXGLOVE_LOG_LEVEL = Object.freeze({ debug: 1, info: 2, warn: 3, error: 4 });

/** A Foxglove `time` from nanoseconds since the epoch. */
export function foxgloveTime(ns: bigint): { sec: number; nsec: number } {
  return { sec: Number(ns / 1_000_000_000n), nsec: Number(ns % 1_000_000_000n) };
}

/** The quaternion of a REP-103 yaw, pitch and roll (radians, ZYX). */
export function quaternionFromEuler(
  yaw: number,
  pitch: number,
  roll: number,
): { x: number; y: number; z: number; w: number } {
  const [cy, sy] = [Math.cos(yaw / 2), Math.sin(yaw / 2)];
  const [cp, sp] = [Math.cos(pitch / 2), Math.sin(pitch / 2)];
  const [cr, sr] = [Math.cos(roll / 2), Math.sin(roll / 2)];
  return {
    x: sr * cp * cy - cr * sp * sy,
    y: cr * sp * cy + sr * cp * sy,
    z: cr * cp * sy - sr * sp * cy,
    w: cr * cp * cy + sr * sp * sy,
  };
}
