// `hal look`'s text for people: the objects seen (bearing, distance, where in the odometry frame,
// how sure, what is cut off) and how far the floor is free per 5 degrees of bearing.
import type { LookDocument, LookObject } from './look-document.js';

const signed = (value: number, digits: number): string =>
  `${value >= 0 ? '+' : '-'}${Math.abs(value).toFixed(digits)}`;

const CUT_OFF: Record<LookObject['cutOff'][number], string> = {
  base: 'its base is below the image (nearer than it says)',
  side: 'cut by the image edge',
  top: 'its top is above the image',
};

function objectLine(o: LookObject, width: number): string {
  const cut =
    o.cutOff.length === 0 ? '' : `  cut off: ${o.cutOff.map((c) => CUT_OFF[c]).join(', ')}`;
  return (
    `  ${o.label.padEnd(width)}  bearing ${signed(o.bearingDeg, 1).padStart(6)}°  ` +
    `distance ${o.distanceM.toFixed(2)} m  at x ${o.world.xM.toFixed(2)} m, y ${o.world.yM.toFixed(2)} m  ` +
    `confidence ${o.confidence.toFixed(2)}${cut}`
  );
}

/** The text of one look. */
export function lookText(doc: LookDocument): string {
  const { pose } = doc;
  const lines = [
    `${doc.robot} (${doc.deviceId}) at x ${pose.xM.toFixed(2)} m, y ${pose.yM.toFixed(2)} m, heading ${pose.yawDeg.toFixed(1)}° (odometry)`,
  ];
  if (!doc.floorKnown) lines.push('the floor could not be learnt: free space is unknown');
  if (doc.objects.length === 0) lines.push('no objects in view');
  else {
    lines.push(
      `${doc.objects.length} object${doc.objects.length === 1 ? '' : 's'} in view (bearing left +, world position in the odometry frame):`,
    );
    const width = Math.max(...doc.objects.map((o) => o.label.length));
    for (const o of doc.objects) lines.push(objectLine(o, width));
  }
  lines.push(`free floor per 5° of bearing (left +, out to ${doc.rangeM} m):`);
  for (const bin of doc.freeSpace) {
    const what = !bin.blocked
      ? `free to ${bin.freeM.toFixed(2)} m`
      : bin.atEdge
        ? `blocked at ${bin.freeM.toFixed(2)} m or nearer (below the image)`
        : `free to ${bin.freeM.toFixed(2)} m, then something`;
    lines.push(`  ${signed(bin.bearingDeg, 0).padStart(4)}°  ${what}`);
  }
  if (doc.saved !== undefined) lines.push(`annotated frame saved to ${doc.saved}`);
  return `${lines.join('\n')}\n`;
}
