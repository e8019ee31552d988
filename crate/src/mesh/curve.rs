//! (being written: see the geometry brief)
