// Waits for a camera to serve new frames: a frame is rendered when it is sent, so once a few more
// have gone out since a motion ended, the latest shows where the motion left the robot.

/** The camera's frames served so far, from its GET /status. */
async function servedFrames(url: string, token: string | undefined): Promise<number> {
  const response = await fetch(`${url}/status`, {
    ...(token === undefined ? {} : { headers: { Authorization: `Bearer ${token}` } }),
  });
  const status = (await response.json()) as { frames_served: number };
  return status.frames_served;
}

/** Resolves once the camera at `url` has sent `count` more frames than now; rejects after 5 s. */
export async function framesLater(url: string, token?: string, count = 3): Promise<void> {
  const target = (await servedFrames(url, token)) + count;
  const deadline = Date.now() + 5000;
  while ((await servedFrames(url, token)) < target) {
    if (Date.now() > deadline) throw new Error(`the camera at ${url} sent no new frames in 5 s`);
    await new Promise((resolve) => setTimeout(resolve, 30));
  }
}
