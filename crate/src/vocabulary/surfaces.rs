//! The words of surface declarations (`#surface X petal contact 0 0 0 …`): the shapes of the
//! organ library and the frame words of a cpfg `.s` file's header.

use super::params::text;
use serde::Serialize;

/// A shape of the organ library, shipped with the core (`crate::model::surface` holds its patches).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Organ {
    Leaf,
    Petal,
    Sepal,
    Disk,
    RayFloret,
}

/// One shape of the library.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct OrganInfo {
    /// As written after `#surface X`.
    pub name: &'static str,
    pub organ: Organ,
    pub doc: &'static str,
}

/// The organ library, in the order of docs/LANGUAGE.md.
#[rustfmt::skip]
pub const SURFACE_SHAPES: &[OrganInfo] = &[
    OrganInfo { name: "leaf", organ: Organ::Leaf, doc: text("A simple leaf: lanceolate, its midrib folded up a little and its tip curved down (2 patches).") },
    OrganInfo { name: "petal", organ: Organ::Petal, doc: text("A petal: narrow claw, broad rounded blade, cupped (2 patches).") },
    OrganInfo { name: "sepal", organ: Organ::Sepal, doc: text("A sepal: a small pointed green leaf of the calyx, cupped inwards (2 patches).") },
    OrganInfo { name: "disk", organ: Organ::Disk, doc: text("A disk of diameter 1 centred on the turtle, facing U, domed a little: a flower's centre or a capitulum (4 patches).") },
    OrganInfo { name: "ray_floret", organ: Organ::RayFloret, doc: text("A ray floret: a long narrow strap with a notched tip, as on a daisy or sunflower head (2 patches).") },
];

/// The word after which a `#surface` line gives part of its frame, as a cpfg `.s` header does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum FrameWord {
    /// `CONTACT POINT`: the point placed at the turtle.
    Contact,
    /// `HEADING`: the direction laid along the turtle's H.
    Heading,
    /// `UP`: the direction laid along the turtle's U.
    Up,
    /// `END POINT`: where the turtle moves after drawing.
    End,
    /// `SIZE`: the file's size; the points are divided by it.
    Size,
    /// The view file's scale (`surface: X file.s scale`): the points are multiplied by it.
    Scale,
    /// `PRECISION S: T:`: quads per patch along s and t.
    Precision,
}

/// One frame word.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct FrameWordInfo {
    pub name: &'static str,
    pub word: FrameWord,
    /// How many numbers follow it.
    pub numbers: usize,
    pub doc: &'static str,
}

#[rustfmt::skip]
pub const FRAME_WORDS: &[FrameWordInfo] = &[
    FrameWordInfo { name: "contact", word: FrameWord::Contact, numbers: 3, doc: text("The point of the patches placed at the turtle (default 0 0 0).") },
    FrameWordInfo { name: "heading", word: FrameWord::Heading, numbers: 3, doc: text("The direction laid along the turtle's heading H (default 0 1 0).") },
    FrameWordInfo { name: "up", word: FrameWord::Up, numbers: 3, doc: text("The direction laid along the turtle's up U (default 0 0 1).") },
    FrameWordInfo { name: "end", word: FrameWord::End, numbers: 3, doc: text("Where the turtle moves after drawing the surface, as cpfg does (default: it stays).") },
    FrameWordInfo { name: "size", word: FrameWord::Size, numbers: 1, doc: text("The size the points are given in: they are divided by it (default 1).") },
    FrameWordInfo { name: "scale", word: FrameWord::Scale, numbers: 1, doc: text("The points are multiplied by it, as by a view file's surface line (default 1).") },
    FrameWordInfo { name: "precision", word: FrameWord::Precision, numbers: 2, doc: text("Quads per patch along s and t, 1 to 32 (default 5 5, as cpfg).") },
];

/// The word after a `#patch` line's 16 points that gives the patch's colours: `color top
/// [bottom]`, colour indices as `;(n)` sets them, the bottom the top's when not given; 0 is the
/// turtle's colour (cpfg's `TOP COLOR` and `BOTTOM COLOR`).
pub const PATCH_COLOR: &str = "color";

/// The library shape named `name`.
pub fn organ_named(name: &str) -> Option<&'static OrganInfo> {
    SURFACE_SHAPES.iter().find(|o| o.name == name)
}

/// The frame word `name`.
pub fn frame_word_named(name: &str) -> Option<&'static FrameWordInfo> {
    FRAME_WORDS.iter().find(|w| w.name == name)
}

impl Organ {
    /// Its name as written.
    pub fn name(self) -> &'static str {
        SURFACE_SHAPES
            .iter()
            .find(|o| o.organ == self)
            .map_or("", |o| o.name)
    }
}

impl FrameWord {
    /// Its name as written.
    pub fn name(self) -> &'static str {
        FRAME_WORDS
            .iter()
            .find(|w| w.word == self)
            .map_or("", |w| w.name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_organ_and_frame_word_has_one_row() {
        for o in SURFACE_SHAPES {
            assert_eq!(organ_named(o.name).map(|r| r.organ), Some(o.organ));
            assert_eq!(o.organ.name(), o.name);
        }
        for w in FRAME_WORDS {
            assert_eq!(frame_word_named(w.name).map(|r| r.word), Some(w.word));
            assert_eq!(w.word.name(), w.name);
            assert!(organ_named(w.name).is_none());
        }
        assert!(organ_named("stamen").is_none());
    }
}
