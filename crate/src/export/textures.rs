//! The texture images the exports carry: embedded in the glTF binary, written beside the POV-Ray
//! scene.

/// The bark texture (tileable, RGB), as shipped in `public/textures/`.
pub const BARK_PNG: &[u8] = include_bytes!("../../../public/textures/bark.png");
/// The leaf texture (RGBA, transparent around the leaf), as shipped in `public/textures/`.
pub const LEAF_PNG: &[u8] = include_bytes!("../../../public/textures/leaf.png");
