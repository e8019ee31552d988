//! What a probe reads from the light grid: the exposure of the voxel it is in and the direction
//! of most light (the module doc of `light` says how both are defined).

use super::{sun, Light, LightSettings};

/// Up: where the sky's light comes from.
const UP: [f64; 3] = [0.0, 1.0, 0.0];

impl Light {
    /// The sky's and the sun's light (each 0 to 1) of voxel `v`.
    fn lights(&self, v: usize) -> (f64, f64) {
        let diffuse = if self.sky_counts() {
            let s = f64::from(self.shadow[v]);
            ((self.full - s + self.settings.shadow) / self.full).clamp(0.0, 1.0)
        } else {
            1.0
        };
        let direct = if self.sun_counts() {
            sun::transmitted(self.beam[v], self.settings.absorb)
        } else {
            1.0
        };
        (diffuse, direct)
    }

    /// The exposure of diffuse and direct light together.
    fn mixed(&self, (diffuse, direct): (f64, f64)) -> f64 {
        let LightSettings { sky, sun, .. } = self.settings;
        (sky * diffuse + sun * direct) / (sky + sun)
    }

    /// The exposure of voxel `v`.
    pub(super) fn exposure_of(&self, v: usize) -> f64 {
        self.mixed(self.lights(v))
    }

    /// The light arriving from the sky and the sun, unshaded by the neighbours.
    fn arriving(&self, (diffuse, direct): (f64, f64)) -> [f64; 3] {
        let LightSettings { sky, sun, .. } = self.settings;
        let toward = self.settings.sun_direction;
        [0, 1, 2].map(|a| (sky * diffuse * UP[a] + sun * direct * toward[a]) / (sky + sun))
    }

    /// The reply to a probe at `p`: exposure, dx, dy, dz.
    pub(super) fn read(&self, p: [f64; 3]) -> [f64; 4] {
        let finite = p.iter().all(|x| x.is_finite());
        let Some(voxel) = self.extent.voxel_of(p).filter(|_| finite) else {
            let lights = (1.0, self.leaving_light(p));
            return reply(self.mixed(lights), self.arriving(lights));
        };
        let centre = self.extent.index(voxel);
        let lights = self.lights(centre);
        let exposure = self.mixed(lights);
        let gradient = self.gradient(voxel, lights);
        let depth = self.settings.depth as f64;
        let arriving = self.arriving(lights);
        reply(
            exposure,
            [0, 1, 2].map(|a| arriving[a] + depth * gradient[a]),
        )
    }

    /// The gradient of the exposure at `voxel` (per voxel) by its 26 neighbours: for a field
    /// growing by g a voxel, Σ (E(n) − E) n / |n|² = (26 / 3) g. The sky's part only across (x
    /// and z: where the gaps are): up and down it says little, since a pyramid spreads its
    /// shadow thinner the deeper it goes and a point under a wide canopy would be told to grow
    /// down. The sun's part in all three. A neighbour beyond the grid reads as the voxel at its side.
    fn gradient(&self, voxel: [usize; 3], (diffuse, direct): (f64, f64)) -> [f64; 3] {
        let dims = self.extent.dims;
        let mut sum = [[0.0; 3]; 2];
        for d in 0..27 {
            let step = [d % 3, d / 3 % 3, d / 9].map(|x| x as isize - 1);
            if step == [0, 0, 0] {
                continue;
            }
            let at = [0, 1, 2]
                .map(|a| (voxel[a] as isize + step[a]).clamp(0, dims[a] as isize - 1) as usize);
            let (d, t) = self.lights(self.extent.index(at));
            let length2 = step.iter().map(|s| (s * s) as f64).sum::<f64>();
            for a in 0..3 {
                sum[0][a] += (d - diffuse) * step[a] as f64 / length2;
                sum[1][a] += (t - direct) * step[a] as f64 / length2;
            }
        }
        let LightSettings { sky, sun, .. } = self.settings;
        let across = [1.0, 0.0, 1.0];
        [0, 1, 2]
            .map(|a| (sky * across[a] * sum[0][a] + sun * sum[1][a]) * 3.0 / 26.0 / (sky + sun))
    }

    /// The sun's light at `p` outside the grid: as the beam towards `p` leaves the grid (the
    /// voxel where the ray from `p` towards the sun enters it), or 1 when the ray misses it.
    fn leaving_light(&self, p: [f64; 3]) -> f64 {
        if !self.sun_counts() || self.extent.voxels() == 0 || p.iter().any(|x| !x.is_finite()) {
            return 1.0;
        }
        let toward = self.settings.sun_direction;
        let origin = self.extent.origin();
        let (mut enter, mut exit) = (0.0f64, f64::INFINITY);
        for a in 0..3 {
            let low = origin[a];
            let high = origin[a] + self.extent.dims[a] as f64 * self.extent.cell;
            if toward[a] == 0.0 {
                if p[a] < low || p[a] > high {
                    return 1.0;
                }
                continue;
            }
            let (t1, t2) = ((low - p[a]) / toward[a], (high - p[a]) / toward[a]);
            enter = enter.max(t1.min(t2));
            exit = exit.min(t1.max(t2));
        }
        if enter > exit {
            return 1.0;
        }
        let at = [0, 1, 2].map(|a| p[a] + enter * toward[a]);
        let v = self.extent.index(self.extent.voxel_clamped(at));
        sun::transmitted(self.beam[v], self.settings.absorb)
    }
}

/// The exposure and the unit direction of `light` ((0, 1, 0) when it is 0).
fn reply(exposure: f64, light: [f64; 3]) -> [f64; 4] {
    let length = light.iter().map(|x| x * x).sum::<f64>().sqrt();
    let [x, y, z] = if length > 1e-9 && length.is_finite() {
        light.map(|c| c / length)
    } else {
        UP
    };
    [exposure, x, y, z]
}
