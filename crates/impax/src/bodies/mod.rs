//! Planar bodies.
