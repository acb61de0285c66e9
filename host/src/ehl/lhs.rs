//! Latin-hypercube sampling of the PHYSICS.md §5.3 input domain.
