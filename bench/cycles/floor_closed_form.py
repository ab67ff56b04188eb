# many_lights' floor at max depth 1 against Lambert's closed form, at each pixel's centre, for ours and
# for Cycles (bench/README.md, "The residues"). Run inside Blender (it reads the EXR images):
#
#   blender -b --factory-startup --python-exit-code 1 -P bench/cycles/floor_closed_form.py -- \
#       bench/cycles/many_lights_direct.json OURS.exr CYCLES.exr
#
# with the two images `./lab bench cycles-accuracy bench/cycles/many_lights_direct.json` leaves in
# build/bench/cycles_accuracy/. Used are the floor pixels whose centre sees every lamp whole or not at all
# (the balls' shadows tested on the segments to each lamp's four corners and its centre) and whose camera
# ray passes no closer than 1.08 radii to a ball's centre; the pixel is albedo / pi x sum of L E, E by
# Lambert's formula for the lamp's square. Prints renderer / closed form - 1 (%) over those pixels per
# channel, and per region of the 4 x 4 grid (red; regions of fewer than 200 such pixels: --).
import sys, json, math, bpy, numpy as np
scene, *imgs = sys.argv[sys.argv.index('--') + 1:]
d = json.load(open(scene)); mats = d['materials']
def load(p):
    im = bpy.data.images.load(p); w, h = im.size
    return np.array(im.pixels[:], dtype=np.float64).reshape(h, w, 4)[::-1, :, :3]
lamps, balls = [], []
for o in d['objects']:
    if o['material'].startswith('lamp'):
        lamps.append((np.array(o['vertices'], float), np.array(mats[o['material']]['emission'], float)))
    elif o['type'] == 'sphere':
        balls.append((np.array(o['transform'][0]['translate'], float), o['radius']))
albedo = np.array(mats['floor']['albedo'])
cam = d['camera']; W, H = d['film']['width'], d['film']['height']
eye = np.array(cam['position'], float); tgt = np.array(cam['target'], float); up = np.array(cam['up'], float)
w = eye - tgt; w /= np.linalg.norm(w); u = np.cross(up, w); u /= np.linalg.norm(u); v = np.cross(w, u)
th = math.tan(math.radians(cam['vertical_fov']) / 2); tw = th * W / H
px, py = np.meshgrid((np.arange(W) + 0.5) / W, (np.arange(H) + 0.5) / H)
dirs = (2 * px - 1)[..., None] * tw * u + (1 - 2 * py)[..., None] * th * v - w
dirs /= np.linalg.norm(dirs, axis=-1, keepdims=True)
t = -eye[1] / np.minimum(dirs[..., 1], -1e-9)
P = eye + t[..., None] * dirs
ok = (dirs[..., 1] < 0) & (np.abs(P[..., 0]) < 6.9) & (P[..., 2] > -43.9)
for c, r in balls:  # away from the balls' silhouettes (and not on them)
    oc = c - eye; tc = (dirs @ oc); dist = np.linalg.norm(eye + tc[..., None] * dirs - c, axis=-1)
    ok &= dist > 1.08 * r
idx = np.nonzero(ok); Q = P[idx]
E = np.zeros((Q.shape[0], 3))
def seg_blocked(A, B):
    blocked = np.zeros(A.shape[0], bool)
    for c, r in balls:
        dvec = B - A; L2 = np.sum(dvec * dvec, 1); tt = np.clip(np.sum((c - A) * dvec, 1) / L2, 0, 1)
        blocked |= np.linalg.norm(A + tt[:, None] * dvec - c, axis=1) < r
    return blocked
n = np.array([0, 1.0, 0])
for vtx, L in lamps:
    pts = list(vtx) + [vtx.mean(0)]
    vis = np.stack([~seg_blocked(Q, np.broadcast_to(p, Q.shape)) for p in pts], 1)
    allv, nonev = vis.all(1), ~vis.any(1)
    ok_pt = allv | nonev
    idx_bad = ~ok_pt
    R = vtx[None, :, :] - Q[:, None, :]; R /= np.linalg.norm(R, axis=2, keepdims=True)
    s = np.zeros(Q.shape[0])
    for i in range(4):
        a, b = R[:, i], R[:, (i + 1) % 4]
        cr = np.cross(a, b); crn = np.linalg.norm(cr, axis=1)
        s += np.arccos(np.clip(np.sum(a * b, 1), -1, 1)) * (cr @ n) / crn
    e = np.abs(s) / 2  # irradiance per unit radiance (Lambert)
    E += np.where(allv, e, 0)[:, None] * L[None, :]
    E[idx_bad] = np.nan
CF = np.full((H, W, 3), np.nan); CF[idx] = albedo / math.pi * E
valid = ~np.isnan(CF[..., 0])
print("valid pixels:", valid.sum(), "of", W * H)
for name, p in zip(["ours", "Cycles"], imgs):
    I = load(p)
    print(name, "whole: " + " ".join("%+.3f" % (100 * (I[..., c][valid].sum() / CF[..., c][valid].sum() - 1)) for c in range(3)))
    for gy in range(4):
        row = []
        for gx in range(4):
            sl = (slice(gy * H // 4, (gy + 1) * H // 4), slice(gx * W // 4, (gx + 1) * W // 4))
            m = valid[sl]
            row.append("%d %d (%4d): %+.2f" % (gx, gy, m.sum(), 100 * (I[sl][..., 0][m].sum() / CF[sl][..., 0][m].sum() - 1)) if m.sum() > 200 else "%d %d: --" % (gx, gy))
        print("  " + " | ".join(row))
