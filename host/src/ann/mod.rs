//! Film network training (placeholder until step 2).
