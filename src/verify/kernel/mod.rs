//! The trusted core: what a verdict is, and the one door through which a `proved` passes.

pub mod checked;
