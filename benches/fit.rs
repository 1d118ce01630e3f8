//! (stub; filled by its issue)
fn main() {}
