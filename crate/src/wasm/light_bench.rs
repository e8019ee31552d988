//! The light program's benchmark (`npm run bench`, issue 47: one light step for 100,000 segments
//! in a 128³ grid within 50 ms): random segments and probes in a box the size of the grid asked
//! for, and the program's two calls, each timed by the script, not here.

use crate::environment::light::Light;
use crate::environment::{Part, Probe, Responder, MAX_ENVIRONMENT_BYTES};
use crate::model::{ProgramSpec, SettingValue};
use crate::vocabulary::EnvironmentProgram;
use rand::{RngExt, SeedableRng};
use wasm_bindgen::prelude::*;

/// A light program with its parts and probes, ready to be updated and asked.
#[wasm_bindgen]
pub struct LightBench {
    light: Light,
    parts: Vec<Part>,
    probes: Vec<Probe<'static>>,
    replies: Vec<f64>,
}

#[wasm_bindgen]
impl LightBench {
    /// `segments` segments of one cell and `probes` probes, at random (from `seed`) in a box
    /// whose light grid is `grid` voxels along each axis (the default settings' margins
    /// included), with the sky and a sun a little off overhead. The segments come as a turtle
    /// draws them: branches of 100 segments end to end, each turning a little from the one before.
    #[wasm_bindgen(constructor)]
    pub fn new(segments: u32, probes: u32, grid: u32, seed: u32) -> Result<LightBench, JsError> {
        let line = |name: &'static str, values: &[f64]| SettingValue {
            name,
            values: values.to_vec(),
            span: 0..0,
        };
        let spec = ProgramSpec {
            program: EnvironmentProgram::Light,
            shape: None,
            settings: vec![line("sun", &[1.0]), line("sun_direction", &[0.3, 1.0, 0.2])],
            span: 0..0,
        };
        let light = Light::new(&spec, 1.0).map_err(|d| JsError::new(&d.message))?;
        let depth = light.settings().depth as f64;
        // The grid adds `depth` voxels each side across and below, one above.
        let across = f64::from(grid) - 2.0 * depth - 1e-6;
        let up = f64::from(grid) - depth - 1.0 - 1e-6;
        let size = [across, up, across];
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(u64::from(seed));
        let point = |rng: &mut rand_pcg::Pcg64Mcg| size.map(|s| rng.random::<f64>() * s);
        let parts = branches(segments, size, &mut rng);
        let probes: Vec<Probe<'static>> = (0..probes)
            .map(|_| Probe {
                position: point(&mut rng),
                heading: [0.0, 1.0, 0.0],
                up: [1.0, 0.0, 0.0],
                args: &[],
                plant: 0,
            })
            .collect();
        Ok(LightBench {
            light,
            parts,
            replies: vec![0.0; 4 * probes.len()],
            probes,
        })
    }

    /// One update: the grid rebuilt from the parts.
    pub fn update(&mut self) -> Result<(), JsError> {
        self.light
            .update(&self.parts, MAX_ENVIRONMENT_BYTES)
            .map_err(|e| JsError::new(&e.what))
    }

    /// Every probe answered; the sum of their exposures.
    pub fn answer(&mut self) -> f64 {
        self.light.answer(&self.probes, &mut self.replies, 4, 0);
        self.replies.iter().step_by(4).sum()
    }

    /// The grid's voxels along x, y and z after the last update.
    pub fn dims(&self) -> Vec<u32> {
        self.light.dims().iter().map(|&d| d as u32).collect()
    }

    /// Bytes the program holds.
    pub fn bytes(&self) -> f64 {
        self.light.bytes() as f64
    }
}

/// `count` segments of length 1 in the box from 0 to `size`: branches of 100, each from a random
/// point, each segment starting where the one before ended and turning by up to about 30°.
fn branches(count: u32, size: [f64; 3], rng: &mut rand_pcg::Pcg64Mcg) -> Vec<Part> {
    let random = |rng: &mut rand_pcg::Pcg64Mcg| [0; 3].map(|_| rng.random::<f64>() * 2.0 - 1.0);
    let unit = |d: [f64; 3]| {
        let length = d.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-9);
        d.map(|x| x / length)
    };
    let mut parts = Vec::with_capacity(count as usize);
    let (mut from, mut heading) = ([0.0; 3], [0.0, 1.0, 0.0]);
    for i in 0..count {
        if i % 100 == 0 {
            from = [0, 1, 2].map(|a| rng.random::<f64>() * size[a]);
            heading = unit(random(rng));
        }
        let turn = random(rng);
        heading = unit([0, 1, 2].map(|a| heading[a] + 0.5 * turn[a]));
        let to = [0, 1, 2].map(|a| (from[a] + heading[a]).clamp(0.0, size[a]));
        parts.push(Part {
            from,
            to,
            radius: 0.05,
            area: 0.0,
            plant: 0,
        });
        from = to;
    }
    parts
}
