/*
 * Foxglove's well-known scene and grid schemas (foxglove.SceneUpdate, foxglove.Grid) as JSON
 * Schema, for what perception believes: the objects it remembers and the occupancy grid it maps.
 * Only the primitives we write are spelled out in full; the others are arrays of objects, which
 * a JSON recording may leave empty.
 */
import { pose, time, vector3 } from './foxglove-schemas.js';
import type { NamedJsonSchema } from './foxglove-schemas.js';

const duration = {
  type: 'object',
  title: 'duration',
  properties: { sec: { type: 'integer' }, nsec: { type: 'integer', minimum: 0 } },
  required: ['sec', 'nsec'],
} as const;

const color = {
  type: 'object',
  title: 'foxglove.Color',
  properties: {
    r: { type: 'number', minimum: 0, maximum: 1 },
    g: { type: 'number', minimum: 0, maximum: 1 },
    b: { type: 'number', minimum: 0, maximum: 1 },
    a: { type: 'number', minimum: 0, maximum: 1 },
  },
  required: ['r', 'g', 'b', 'a'],
} as const;

const cube = {
  type: 'object',
  title: 'foxglove.CubePrimitive',
  properties: { pose, size: vector3, color },
  required: ['pose', 'size', 'color'],
} as const;

const cylinder = {
  type: 'object',
  title: 'foxglove.CylinderPrimitive',
  properties: {
    pose,
    size: vector3,
    bottom_scale: { type: 'number' },
    top_scale: { type: 'number' },
    color,
  },
  required: ['pose', 'size', 'bottom_scale', 'top_scale', 'color'],
} as const;

const text = {
  type: 'object',
  title: 'foxglove.TextPrimitive',
  properties: {
    pose,
    billboard: { type: 'boolean' },
    font_size: { type: 'number' },
    scale_invariant: { type: 'boolean' },
    color,
    text: { type: 'string' },
  },
  required: ['pose', 'billboard', 'font_size', 'scale_invariant', 'color', 'text'],
} as const;

const others = { type: 'array', items: { type: 'object' } } as const;

const entity = {
  type: 'object',
  title: 'foxglove.SceneEntity',
  properties: {
    timestamp: time,
    frame_id: { type: 'string' },
    id: { type: 'string' },
    lifetime: duration,
    frame_locked: { type: 'boolean' },
    metadata: {
      type: 'array',
      items: {
        type: 'object',
        title: 'foxglove.KeyValuePair',
        properties: { key: { type: 'string' }, value: { type: 'string' } },
        required: ['key', 'value'],
      },
    },
    arrows: others,
    cubes: { type: 'array', items: cube },
    spheres: others,
    cylinders: { type: 'array', items: cylinder },
    lines: others,
    triangles: others,
    texts: { type: 'array', items: text },
    models: others,
  },
  required: ['timestamp', 'frame_id', 'id', 'lifetime', 'frame_locked', 'metadata'],
} as const;

export const SCENE_UPDATE: NamedJsonSchema = {
  name: 'foxglove.SceneUpdate',
  schema: {
    title: 'foxglove.SceneUpdate',
    description: 'An update to the entities displayed in a 3D scene',
    type: 'object',
    properties: {
      deletions: {
        type: 'array',
        items: {
          type: 'object',
          title: 'foxglove.SceneEntityDeletion',
          properties: {
            timestamp: time,
            type: {
              type: 'integer',
              description: 'MATCHING_ID 0, ALL 1',
              enum: [0, 1],
            },
            id: { type: 'string' },
          },
          required: ['timestamp', 'type', 'id'],
        },
      },
      entities: { type: 'array', items: entity },
    },
    required: ['deletions', 'entities'],
  },
};

/** foxglove.NumericType: the type of a packed field. */
export const NUMERIC_TYPE = Object.freeze({ UINT8: 1, INT8: 2, FLOAT32: 7 });

export const GRID: NamedJsonSchema = {
  name: 'foxglove.Grid',
  schema: {
    title: 'foxglove.Grid',
    description: 'A 2D grid of data',
    type: 'object',
    properties: {
      timestamp: time,
      frame_id: { type: 'string' },
      pose: { ...pose, description: "Origin of the grid's corner relative to its frame" },
      column_count: { type: 'integer', minimum: 0 },
      cell_size: {
        type: 'object',
        title: 'foxglove.Vector2',
        properties: { x: { type: 'number' }, y: { type: 'number' } },
        required: ['x', 'y'],
      },
      row_stride: { type: 'integer', minimum: 0 },
      cell_stride: { type: 'integer', minimum: 0 },
      fields: {
        type: 'array',
        items: {
          type: 'object',
          title: 'foxglove.PackedElementField',
          properties: {
            name: { type: 'string' },
            offset: { type: 'integer', minimum: 0 },
            type: {
              type: 'integer',
              description:
                'UNKNOWN 0, UINT8 1, INT8 2, UINT16 3, INT16 4, UINT32 5, INT32 6, FLOAT32 7, FLOAT64 8',
              enum: [0, 1, 2, 3, 4, 5, 6, 7, 8],
            },
          },
          required: ['name', 'offset', 'type'],
        },
      },
      data: { type: 'string', contentEncoding: 'base64' },
    },
    required: [
      'timestamp',
      'frame_id',
      'pose',
      'column_count',
      'cell_size',
      'row_stride',
      'cell_stride',
      'fields',
      'data',
    ],
  },
};
