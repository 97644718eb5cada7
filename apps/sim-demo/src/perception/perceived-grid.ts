import { OccupancyGrid } from '@hal/navigation';
import type { WorldMap } from '@hal/simulation';
import type { OccupancyGridView } from '@hal/simulation/three';

/** A grid over the map's arena that starts all unknown: only what the camera saw goes in. */
export function emptyGridOf(map: WorldMap): OccupancyGrid {
  const { width, height } = map.arena;
  return new OccupancyGrid({ widthM: width, heightM: height, resolutionM: 0.05 });
}

/** The grid as the scene's floor overlay draws it: occupancy 0..1 (free clear), unknown -1. */
export function perceivedGridView(grid: OccupancyGrid): OccupancyGridView {
  const { spec, logOdds } = grid;
  return {
    width: spec.width,
    height: spec.height,
    resolution: spec.resolutionM,
    origin: { x: spec.originX, y: spec.originY },
    data: Array.from(logOdds, (l) => (l === 0 ? -1 : 1 / (1 + Math.exp(-l)))),
  };
}
