//! PNG pictures for the command line (`export --frames N --format png`, `--at T -o OUT.png`): the
//! SVG's picture ([`svg::Flat`]: lines with round caps, filled outlines and circles, in 2D, as the
//! SVG draws them) filled on the CPU, without a GPU: each shape's coverage of a pixel counted on
//! four sub-rows and exactly along each, blended in drawing order, and the pixels written as an
//! RGBA PNG (deflated by `miniz_oxide`, which the importers already use). Not the studio's 3D
//! view: no lights, no tubes, the plant seen from +Z as in the SVG.

use glam::DVec2;
use meristem::export::svg::{Flat, FlatShape};

/// The largest side of a PNG picture, in pixels (its pixels are held whole while it is written).
pub const MAX_SIDE: u32 = 4096;

/// Sub-rows each row of pixels is sampled on.
const SUB_ROWS: usize = 4;

/// The picture as an RGBA PNG file.
pub fn png(flat: &Flat) -> Vec<u8> {
    let (width, height) = (flat.width as usize, flat.height as usize);
    let mut canvas = Canvas {
        width,
        height,
        rgba: match flat.background {
            Some([r, g, b]) => [r, g, b, 255].repeat(width * height),
            None => vec![0; 4 * width * height],
        },
        coverage: Vec::new(),
    };
    for (shape, colour) in &flat.shapes {
        let outline = match shape {
            FlatShape::Line(a, b, w) => capsule(*a, *b, 0.5 * w),
            FlatShape::Fill(points) => points.clone(),
            FlatShape::Circle(c, r) => circle(*c, *r, 32),
        };
        canvas.fill(&outline, *colour);
    }
    encode(width, height, &canvas.rgba)
}

/// A round-capped stroke from `a` to `b`, `half` wide on each side, as an outline.
fn capsule(a: DVec2, b: DVec2, half: f64) -> Vec<DVec2> {
    let Some(along) = (b - a).try_normalize() else {
        return circle(a, half, 16);
    };
    let steps = 8;
    let mut out = Vec::with_capacity(2 * steps + 2);
    for (centre, turn) in [(b, -0.5), (a, 0.5)] {
        for k in 0..=steps {
            let angle = std::f64::consts::PI * (turn + k as f64 / steps as f64);
            out.push(centre + half * DVec2::from_angle(angle).rotate(along));
        }
    }
    out
}

/// A circle as an outline of `sides` points.
fn circle(centre: DVec2, radius: f64, sides: usize) -> Vec<DVec2> {
    (0..sides)
        .map(|k| {
            centre + radius * DVec2::from_angle(std::f64::consts::TAU * k as f64 / sides as f64)
        })
        .collect()
}

/// Pixels being drawn (RGBA, rows top down) and the coverage of the shape being filled.
struct Canvas {
    width: usize,
    height: usize,
    rgba: Vec<u8>,
    coverage: Vec<f32>,
}

impl Canvas {
    /// Fills `outline` (even-odd) in `colour`, its edges antialiased by their coverage.
    fn fill(&mut self, outline: &[DVec2], [r, g, b]: [u8; 3]) {
        if outline.len() < 3 || outline.iter().any(|p| !p.is_finite()) {
            return;
        }
        let (lo, hi) = outline
            .iter()
            .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(*p), hi.max(*p))
            });
        let x0 = lo.x.floor().max(0.0) as usize;
        let x1 = (hi.x.ceil().max(0.0) as usize).min(self.width);
        let y0 = lo.y.floor().max(0.0) as usize;
        let y1 = (hi.y.ceil().max(0.0) as usize).min(self.height);
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        let w = x1 - x0;
        self.coverage.clear();
        self.coverage.resize(w * (y1 - y0), 0.0);
        let mut crossings: Vec<f64> = Vec::new();
        for py in y0..y1 {
            let row = &mut self.coverage[(py - y0) * w..(py - y0 + 1) * w];
            for s in 0..SUB_ROWS {
                let y = py as f64 + (s as f64 + 0.5) / SUB_ROWS as f64;
                crossings.clear();
                for (k, a) in outline.iter().enumerate() {
                    let b = outline[(k + 1) % outline.len()];
                    if (a.y <= y) != (b.y <= y) {
                        crossings.push(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
                    }
                }
                crossings.sort_by(f64::total_cmp);
                for span in crossings.chunks_exact(2) {
                    add_span(row, x0, span[0], span[1]);
                }
            }
        }
        for py in y0..y1 {
            for px in x0..x1 {
                let a = (self.coverage[(py - y0) * w + px - x0] / SUB_ROWS as f32).min(1.0);
                if a > 0.0 {
                    blend(
                        &mut self.rgba[4 * (py * self.width + px)..][..4],
                        [r, g, b],
                        a,
                    );
                }
            }
        }
    }
}

/// Adds the span from `xa` to `xb` of one sub-row to `row` (pixels from `x0`): each pixel by how
/// much of it the span covers.
fn add_span(row: &mut [f32], x0: usize, xa: f64, xb: f64) {
    let (from, to) = (xa.max(x0 as f64), xb.min((x0 + row.len()) as f64));
    if to <= from {
        return;
    }
    for px in from.floor() as usize..to.ceil() as usize {
        let cover = to.min(px as f64 + 1.0) - from.max(px as f64);
        row[px - x0] += cover.max(0.0) as f32;
    }
}

/// Draws `colour` at opacity `a` over the RGBA pixel `pixel`.
fn blend(pixel: &mut [u8], colour: [u8; 3], a: f32) {
    let under = f32::from(pixel[3]) / 255.0;
    let out = a + under * (1.0 - a);
    for k in 0..3 {
        let c = (f32::from(colour[k]) * a + f32::from(pixel[k]) * under * (1.0 - a)) / out;
        pixel[k] = c.round().clamp(0.0, 255.0) as u8;
    }
    pixel[3] = (out * 255.0).round() as u8;
}

/// An RGBA PNG of `rgba` (rows top down, 8 bits a channel).
fn encode(width: usize, height: usize, rgba: &[u8]) -> Vec<u8> {
    let mut raw = Vec::with_capacity(height * (4 * width + 1));
    for row in rgba.chunks_exact(4 * width) {
        raw.push(0); // (no filter)
        raw.extend_from_slice(row);
    }
    let mut header = Vec::with_capacity(13);
    header.extend_from_slice(&(width as u32).to_be_bytes());
    header.extend_from_slice(&(height as u32).to_be_bytes());
    header.extend_from_slice(&[8, 6, 0, 0, 0]); // 8 bits, RGBA, deflate, no filter, no interlace
    let mut out = b"\x89PNG\r\n\x1a\n".to_vec();
    chunk(&mut out, b"IHDR", &header);
    chunk(
        &mut out,
        b"IDAT",
        &miniz_oxide::deflate::compress_to_vec_zlib(&raw, 6),
    );
    chunk(&mut out, b"IEND", &[]);
    out
}

/// Appends a PNG chunk: its length, kind, data and CRC.
fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    out.extend_from_slice(&(data.len() as u32).to_be_bytes());
    let from = out.len();
    out.extend_from_slice(kind);
    out.extend_from_slice(data);
    let crc = crc32(&out[from..]);
    out.extend_from_slice(&crc.to_be_bytes());
}

/// The CRC-32 of PNG chunks (ISO 3309, polynomial 0xEDB88320).
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &byte in bytes {
        crc ^= u32::from(byte);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_crc_of_a_png_chunk_is_the_standard_one() {
        // IEND's CRC, printed in every PNG file: AE 42 60 82.
        assert_eq!(crc32(b"IEND"), 0xAE42_6082);
    }

    #[test]
    fn a_square_covers_its_pixels_and_antialiases_its_edges() {
        let flat = Flat {
            width: 4,
            height: 2,
            background: Some([255, 255, 255]),
            shapes: vec![(
                FlatShape::Fill(vec![
                    DVec2::new(0.0, 0.0),
                    DVec2::new(1.5, 0.0),
                    DVec2::new(1.5, 2.0),
                    DVec2::new(0.0, 2.0),
                ]),
                [0, 0, 0],
            )],
        };
        let mut canvas = Canvas {
            width: 4,
            height: 2,
            rgba: [255, 255, 255, 255].repeat(8),
            coverage: Vec::new(),
        };
        if let (FlatShape::Fill(outline), colour) = &flat.shapes[0] {
            canvas.fill(outline, *colour);
        }
        // Pixel 0 covered, pixel 1 half (grey), pixels 2 and 3 untouched.
        assert_eq!(&canvas.rgba[0..4], &[0, 0, 0, 255]);
        assert_eq!(&canvas.rgba[4..8], &[128, 128, 128, 255]);
        assert_eq!(&canvas.rgba[8..16], &[255; 8]);
        let file = png(&flat);
        assert_eq!(&file[..8], b"\x89PNG\r\n\x1a\n");
        assert_eq!(&file[16..24], &[0, 0, 0, 4, 0, 0, 0, 2]);
    }
}
