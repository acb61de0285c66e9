//! Grid-refinement study: solve one case on N, 2N−1 and 4N−3 nodes (every spacing halved each
//! time, see [`super::grid`]) and extrapolate h_c and h_min à la Richardson.
