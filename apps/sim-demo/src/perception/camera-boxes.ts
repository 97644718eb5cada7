import { cameraProjection, pixelOfPoint } from '@hal/kinematics';
import type { CameraProjection } from '@hal/kinematics';
import type { Percept } from '@hal/perception';
import type { CameraModel } from '@hal/types';

/** The colour a palette colour's box is drawn in on the camera view. */
const BOX_COLOURS: Readonly<Record<string, string>> = {
  red: '#ff2828',
  orange: '#ff9600',
  yellow: '#ffe600',
  green: '#28dc3c',
  blue: '#2878ff',
  purple: '#be46ff',
};

/**
 * Draws what perception made of a frame over the camera view: each object boxed in its colour
 * with its label and distance, and the free-space boundary across the floor (cyan where
 * something was seen, white where the floor is free to the range limit). The canvas has the
 * frame's size and lies over the camera's own canvas.
 */
export class CameraBoxes {
  readonly #canvas: HTMLCanvasElement;
  #projection: CameraProjection | undefined;
  #camera: CameraModel | undefined;

  constructor(canvas: HTMLCanvasElement) {
    this.#canvas = canvas;
  }

  /** Clears the overlay. */
  clear(): void {
    this.#canvas.getContext('2d')?.clearRect(0, 0, this.#canvas.width, this.#canvas.height);
  }

  /** Draws `percept`, seen through `camera`. */
  draw(percept: Percept, camera: CameraModel): void {
    const context = this.#canvas.getContext('2d');
    if (context === null) return;
    if (this.#camera !== camera) {
      this.#camera = camera;
      this.#projection = cameraProjection(camera);
    }
    const projection = this.#projection!;
    const { width, height } = this.#canvas;
    const sx = width / percept.width;
    const sy = height / percept.height;
    context.clearRect(0, 0, width, height);
    context.lineWidth = 2;
    // the free-space boundary: one segment per pair of neighbouring columns
    let previous: { x: number; y: number; hit: boolean } | undefined;
    for (const column of percept.freeSpace) {
      const at = pixelOfPoint(projection, { x: column.to.x, y: column.to.y, z: 0 });
      if (at === undefined) {
        previous = undefined;
        continue;
      }
      const point = {
        x: (column.column + 0.5) * sx,
        y: Math.min(at.v, percept.height - 1) * sy,
        hit: column.hit,
      };
      if (previous !== undefined) {
        context.strokeStyle = column.hit ? '#00e6ff' : 'rgba(255, 255, 255, 0.8)';
        context.beginPath();
        context.moveTo(previous.x, previous.y);
        context.lineTo(point.x, point.y);
        context.stroke();
      }
      previous = point;
    }
    context.font = '11px system-ui, sans-serif';
    context.textBaseline = 'top';
    for (const object of percept.objects) {
      const colour = BOX_COLOURS[object.colour] ?? '#ff00ff';
      const { left, top, right, bottom } = object.image;
      const x = left * sx;
      const y = top * sy;
      context.strokeStyle = colour;
      context.strokeRect(x - 1, y - 1, (right - left + 2) * sx, (bottom - top + 2) * sy);
      const text = `${object.label} ${object.distanceM.toFixed(2)} m`;
      const w = context.measureText(text).width + 6;
      const ty = y >= 16 ? y - 16 : y + 2;
      const tx = Math.max(0, Math.min(width - w, x));
      context.fillStyle = 'rgba(20, 20, 20, 0.8)';
      context.fillRect(tx, ty, w, 14);
      context.fillStyle = colour;
      context.fillText(text, tx + 3, ty + 1);
    }
  }
}
