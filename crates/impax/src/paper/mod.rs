//! Reproductions of the source papers.
