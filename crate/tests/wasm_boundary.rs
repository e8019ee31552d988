//! The same plants built by the native core (`cargo test`) and by the core compiled to WebAssembly
//! through its JavaScript boundary (`wasm-pack test --node crate --test wasm_boundary`, part of
//! `npm test`), each checked against one set of expected values: a difference between the native
//! and the wasm core (floating point, memory, the boundary's conversions) fails one of them.
//! The expected values were taken from the native build; the derived strings must match exactly,
//! the geometry to within float rounding.

/// A deterministic plant (ABOP fig. 1.24d) and a stochastic one (fig. 1.27, its random choices from
/// one seeded generator), with the iterations and the seed each build uses.
/// And two plants that sense their world (issue 47), where a last bit of a sine or an exponential
/// can flip a bud: a 3 × 3 stand competing for light and a space-colonisation tree.
const PLANTS: [(&str, &str, u32, u64); 4] = [
    (
        "1.24d",
        include_str!("../../public/examples/abop-1.24d.lsys"),
        6,
        1,
    ),
    (
        "1.27",
        include_str!("../../public/examples/abop-1.27-stochastic.lsys"),
        5,
        42,
    ),
    (
        "open-grid",
        include_str!("../../public/examples/open-grid-competing.lsys"),
        9,
        1,
    ),
    (
        "open-space",
        include_str!("../../public/examples/open-space-colonisation.lsys"),
        20,
        7,
    ),
];

/// What a build gave: the derived string's fingerprint, the vertex count and the sum of the
/// absolute coordinates of every vertex.
#[derive(Debug)]
struct Built {
    hash: String,
    vertices: usize,
    extent: f64,
}

/// The expected builds of [`PLANTS`], in order.
const EXPECTED: [(&str, usize, f64); 4] = [
    ("da7d5a827a04c582", 12719, 1373290.500090927),
    ("6b509c2c41fbe6cc", 8904, 459051.03510469943),
    ("4925332075fa7d0c", 42175, 524549.5325517417),
    ("d0a8f0f5ac4e6c93", 4542, 43900.38167501377),
];

/// Every function of `meristem::maths` at 20,000 arguments spread over its domain, each result's
/// bits folded into one number: the same on every target, or the core's plants are not.
fn maths_fingerprint() -> u64 {
    use meristem::maths;
    let mut folded: u64 = 0xcbf2_9ce4_8422_2325;
    let mut fold = |x: f64| folded = (folded ^ x.to_bits()).wrapping_mul(0x0100_0000_01b3);
    for k in 0..20_000 {
        let t = k as f64 / 20_000.0;
        let x = (t - 0.5) * 200.0; // [-100, 100)
        let (s, c) = maths::sin_cos(x);
        fold(s);
        fold(c);
        fold(maths::tan(x));
        fold(maths::asin(2.0 * t - 1.0));
        fold(maths::acos(2.0 * t - 1.0));
        fold(maths::atan(x));
        fold(maths::atan2(x, 1.0 - t));
        fold(maths::exp(x * 0.7));
        fold(maths::ln(t * 1e3 + 1e-9));
        fold(maths::log10(t * 1e6 + 1e-9));
        fold(maths::powf(t * 10.0, x * 0.1));
        fold(maths::cbrt(x));
        fold(maths::hypot(x, t));
    }
    folded
}

/// [`maths_fingerprint`] as the native build computes it.
const MATHS_FINGERPRINT: u64 = 0xaa9b_3227_b8d0_0a38;

fn extent(positions: &[f32]) -> f64 {
    positions.iter().map(|p| f64::from(p.abs())).sum()
}

fn check(name: &str, built: &Built, expected: (&str, usize, f64)) {
    assert_eq!(built.hash, expected.0, "{name}: derived string");
    assert_eq!(built.vertices, expected.1, "{name}: vertices");
    let relative = (built.extent - expected.2).abs() / expected.2.max(1.0);
    assert!(
        relative < 1e-6,
        "{name}: geometry {} vs {}",
        built.extent,
        expected.2
    );
}

/// Number texts as grammars hold them and as they must not: `meristem::number::parse_f64` reads
/// them as `str::parse::<f64>` does, bit for bit (under wasm32 it lets JavaScript's parseFloat
/// convert the digits it has checked).
fn parse_f64_is_str_parse() {
    for text in meristem::number::PARSE_SAMPLES {
        assert_eq!(
            meristem::number::parse_f64(text).map(f64::to_bits),
            text.parse::<f64>().ok().map(f64::to_bits),
            "{text:?}"
        );
    }
}

/// `number::Decimal` writes a number as Rust's `{}` does (under wasm32 from JavaScript's
/// `toString` digits, without Rust's float formatting in the core).
fn decimal_is_rust_s_display() {
    let samples = [
        0.1,
        1e21,
        -1.5e300,
        1.5e-7,
        -2.5e-8,
        5e-324,
        f64::MAX,
        f64::MIN_POSITIVE,
        1e-6,
        123.456,
        1e20,
        -7.0,
        0.0,
        -0.0,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        1.0 / 3.0,
        2.0 / 3.0 * 1e-10,
        22.5,
        137.5077640500378,
        std::f64::consts::PI,
        1.2345678901234567e25,
        9007199254740993.0,
    ];
    for v in samples {
        assert_eq!(
            format!("{}", meristem::number::Decimal(v)),
            format!("{v}"),
            "{v:?}"
        );
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use super::*;
    use meristem::mesh::MeshOptions;
    use meristem::{build, BuildOptions};

    #[test]
    fn the_native_core_builds_the_expected_plants() {
        for ((name, source, iterations, seed), expected) in PLANTS.iter().zip(EXPECTED) {
            let options = BuildOptions {
                iterations: Some(*iterations),
                seed: Some(*seed),
                time: None,
                mesh: MeshOptions::view(None, None),
                sketch: false,
            };
            let b = build(source, &options);
            assert!(b.ok(), "{name}: {:?}", b.diagnostics);
            let built = Built {
                hash: b.inspector().map(|i| i.derived_hash()).unwrap_or_default(),
                vertices: b.plant.mesh.positions.len() / 3,
                extent: extent(&b.plant.mesh.positions),
            };
            eprintln!("{name}: {built:?}");
            check(name, &built, expected);
        }
    }

    #[test]
    fn numbers_are_read_as_str_parse_reads_them() {
        parse_f64_is_str_parse();
    }

    #[test]
    fn numbers_are_written_as_rust_writes_them() {
        decimal_is_rust_s_display();
    }

    #[test]
    fn the_maths_give_the_same_bits_as_in_webassembly() {
        let fingerprint = maths_fingerprint();
        assert_eq!(fingerprint, MATHS_FINGERPRINT, "{fingerprint:#x}");
    }
}

#[cfg(target_arch = "wasm32")]
mod wasm {
    use super::*;
    use meristem::wasm::{build, build_sketch, version, vocabulary, BuildOptionsObject};
    use wasm_bindgen::{JsCast, JsValue};
    use wasm_bindgen_test::wasm_bindgen_test;

    /// `{ iterations, seed }` as JavaScript passes it.
    fn options(iterations: u32, seed: u64) -> BuildOptionsObject {
        let object = js_sys::Object::new();
        js_sys::Reflect::set(&object, &"iterations".into(), &JsValue::from(iterations)).unwrap();
        js_sys::Reflect::set(&object, &"seed".into(), &JsValue::from(seed as f64)).unwrap();
        object.unchecked_into()
    }

    #[wasm_bindgen_test]
    fn the_wasm_core_builds_the_expected_plants_through_its_boundary() {
        for ((name, source, iterations, seed), expected) in PLANTS.iter().zip(EXPECTED) {
            let b = build(source, &options(*iterations, *seed), None, None)
                .unwrap_or_else(|_| panic!("{name}: build threw"));
            assert!(b.ok(), "{name}: {}", b.diagnostics());
            let positions = b.positions().to_vec();
            let built = Built {
                hash: b.into_inspector().derived_hash(),
                vertices: positions.len() / 3,
                extent: extent(&positions),
            };
            check(name, &built, expected);
        }
    }

    #[wasm_bindgen_test]
    fn numbers_are_read_as_str_parse_reads_them() {
        parse_f64_is_str_parse();
    }

    #[wasm_bindgen_test]
    fn numbers_are_written_as_rust_writes_them() {
        decimal_is_rust_s_display();
    }

    #[wasm_bindgen_test]
    fn the_maths_give_the_same_bits_as_natively() {
        let fingerprint = maths_fingerprint();
        assert_eq!(fingerprint, MATHS_FINGERPRINT, "{fingerprint:#x}");
    }

    #[wasm_bindgen_test]
    fn bad_options_and_bad_grammars_come_back_as_errors_not_crashes() {
        let not_options: BuildOptionsObject = JsValue::from_str("seven").unchecked_into();
        assert!(build("axiom: F", &not_options, None, None).is_err());
        let b = build("axiom: F\nF -> F[", &options(3, 1), None, None).unwrap();
        assert!(!b.ok());
        assert!(b.diagnostics().contains("error"), "{}", b.diagnostics());
    }

    #[wasm_bindgen_test]
    fn mesh_arrays_copy_into_typed_arrays_of_their_length_only() {
        let b = build("axiom: F+F", &options(0, 1), None, None).unwrap();
        let positions = b.positions().to_vec();
        let out = js_sys::Float32Array::new_with_length(positions.len() as u32);
        b.positions_into(&out).unwrap();
        assert_eq!(out.to_vec(), positions);
        let indices = b.indices().to_vec();
        let out = js_sys::Uint32Array::new_with_length(indices.len() as u32);
        b.indices_into(&out).unwrap();
        assert_eq!(out.to_vec(), indices);
        let normals = b.packed_normals().to_vec();
        let out = js_sys::Int16Array::new_with_length(normals.len() as u32);
        b.packed_normals_into(&out).unwrap();
        assert_eq!(out.to_vec(), normals);
        let short = js_sys::Float32Array::new_with_length(positions.len() as u32 - 1);
        assert!(b.positions_into(&short).is_err());
        assert!(b.uvs_into(&short).is_err());
        assert!(b
            .packed_colors_into(&js_sys::Uint8Array::new_with_length(1))
            .is_err());
    }

    #[wasm_bindgen_test]
    fn a_build_with_a_sketch_first_shows_the_sketch_then_meshes_in_the_same_call() {
        use std::cell::RefCell;
        use std::rc::Rc;
        use wasm_bindgen::closure::Closure;
        let source = "#angle 90\naxiom: F+F";
        let sketch = build_sketch(source, None);
        let shown: Rc<RefCell<Vec<(Vec<f32>, Vec<f32>, bool, f64)>>> = Rc::default();
        let record = Rc::clone(&shown);
        let show = Closure::<dyn FnMut(js_sys::Float32Array, js_sys::Float32Array, bool, f64)>::new(
            move |lines: js_sys::Float32Array, colors: js_sys::Float32Array, flat, segments| {
                record
                    .borrow_mut()
                    .push((lines.to_vec(), colors.to_vec(), flat, segments));
            },
        );
        let first = js_sys::Object::new();
        js_sys::Reflect::set(&first, &"minSegments".into(), &JsValue::from(1)).unwrap();
        js_sys::Reflect::set(&first, &"show".into(), show.as_ref()).unwrap();
        let options = js_sys::Object::new();
        js_sys::Reflect::set(&options, &"sketchFirst".into(), &first).unwrap();
        let b = build(source, &options.unchecked_into(), None, None).unwrap();
        let plain = build(source, &JsValue::UNDEFINED.unchecked_into(), None, None).unwrap();
        let shown = shown.borrow();
        assert_eq!(shown.len(), 1);
        assert_eq!(shown[0].0, sketch.lines().to_vec());
        assert_eq!(shown[0].1, sketch.line_colors().to_vec());
        assert_eq!((shown[0].2, shown[0].3), (true, 2.0));
        assert_eq!(b.positions().to_vec(), plain.positions().to_vec());
        assert_eq!(b.lines().length(), 0);
    }

    /// The packed normals are what the page once computed, `Math.round` of the clamped, scaled
    /// value stored in an `Int16Array` (NaN as 0): through the SIMD path when these tests are
    /// built with `+simd128`, as `npm test` builds them (the studio core ships it), through the
    /// scalar one natively (`mesh::pack`'s own tests).
    #[wasm_bindgen_test]
    fn packed_normals_are_math_round_of_the_clamped_scaled_values() {
        let normals = meristem::mesh::normal_samples();
        let packed = meristem::mesh::pack_normals(&normals);
        assert_eq!(packed.len(), normals.len());
        for (&v, &p) in normals.iter().zip(&packed) {
            let want = js_sys::Math::round(f64::from(v).clamp(-1.0, 1.0) * 32767.0);
            let want = if want.is_nan() { 0.0 } else { want };
            assert_eq!(f64::from(p), want, "normal {v}");
        }
    }

    /// A mesh's bounds are the box of its positions, each bound the first of its equal values met
    /// in order (a zero's sign): through the SIMD path under wasm32 with `+simd128`, whose lanes
    /// meet the points in another order.
    #[wasm_bindgen_test]
    fn mesh_bounds_are_the_box_of_the_positions_in_order() {
        let box_of = |positions: &[f32]| {
            let (mut min, mut max) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
            for p in positions.chunks_exact(3) {
                for k in 0..3 {
                    if p[k] < min[k] {
                        min[k] = p[k];
                    }
                    if p[k] > max[k] {
                        max[k] = p[k];
                    }
                }
            }
            [min.map(f64::from), max.map(f64::from)]
        };
        // Bounds of zero reached by zeros of both signs (the first zero met is the bound), with
        // negative values and a NaN: seven points (a group of four and three left over); eight
        // (two groups) whose greatest x is -0 in the first group and +0 in the second, in the
        // lane that the lanes are folded from first; and 13.
        let seven = [
            -0.0,
            1.0,
            -2.0, //
            0.0,
            0.0,
            -3.0, //
            -2.5,
            -0.0,
            0.0, //
            -3.0,
            4.0,
            -0.0, //
            -1.0,
            0.0,
            -5.0, //
            0.0,
            2.0,
            f32::NAN, //
            -0.0,
            0.0,
            -1.5,
        ];
        let eight = [
            -1.0, 1.0, 1.0, //
            -0.0, 1.0, 1.0, //
            -2.0, 1.0, 1.0, //
            -3.0, 1.0, 1.0, //
            0.0, 1.0, 1.0, //
            -4.0, 1.0, 1.0, //
            -5.0, 1.0, 1.0, //
            -6.0, 1.0, 1.0,
        ];
        let thirteen = [&seven[..], &[0.5, -0.0, 0.0, -0.0, 6.0, -5.0].repeat(3)].concat();
        for positions in [&seven[..], &eight, &thirteen] {
            let mesh = meristem::mesh::MeshBuffers {
                positions: positions.to_vec(),
                ..Default::default()
            };
            let (got, want) = (mesh.bounds(), box_of(positions));
            let bits = |b: [[f64; 3]; 2]| b.map(|v| v.map(f64::to_bits));
            assert_eq!(
                bits(got),
                bits(want),
                "{positions:?}: {got:?} against {want:?}"
            );
        }
    }

    #[wasm_bindgen_test]
    fn the_tables_cross_the_boundary() {
        assert_eq!(version(), env!("CARGO_PKG_VERSION"));
        let vocabulary: serde_json::Value = serde_json::from_str(&vocabulary()).unwrap();
        assert!(
            vocabulary["modules"]
                .as_array()
                .is_some_and(|m| m.len() > 20),
            "{vocabulary}"
        );
    }
}
