//! The layout of a certificate file: pretty JSON (two-space indent) down to depth
//! [`FLAT_BELOW`], and each deeper object or array on one line (`{"at": ["0"], "lhs": ["1"],
//! "rhs": ["1"]}`), as docs/certificates.md shows them. A sampled file is mostly such rows;
//! indenting every number of them made the files 3.5 times larger (72% blanks).

use serde_json::ser::{Formatter, PrettyFormatter};
use std::io::{self, Write};

/// The depth (the file's object is 1) below which containers are written on one line.
const FLAT_BELOW: usize = 5;

pub(super) struct Layout {
    pretty: PrettyFormatter<'static>,
    depth: usize,
}

impl Layout {
    pub(super) fn new() -> Layout {
        Layout {
            pretty: PrettyFormatter::new(),
            depth: 0,
        }
    }
    fn flat(&self) -> bool {
        self.depth > FLAT_BELOW
    }
}

impl Formatter for Layout {
    fn begin_array<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.depth += 1;
        if self.flat() {
            w.write_all(b"[")
        } else {
            self.pretty.begin_array(w)
        }
    }
    fn end_array<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        let r = if self.flat() {
            w.write_all(b"]")
        } else {
            self.pretty.end_array(w)
        };
        self.depth -= 1;
        r
    }
    fn begin_array_value<W: ?Sized + Write>(&mut self, w: &mut W, first: bool) -> io::Result<()> {
        if !self.flat() {
            return self.pretty.begin_array_value(w, first);
        }
        if first {
            Ok(())
        } else {
            w.write_all(b", ")
        }
    }
    fn end_array_value<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        if self.flat() {
            Ok(())
        } else {
            self.pretty.end_array_value(w)
        }
    }
    fn begin_object<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.depth += 1;
        if self.flat() {
            w.write_all(b"{")
        } else {
            self.pretty.begin_object(w)
        }
    }
    fn end_object<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        let r = if self.flat() {
            w.write_all(b"}")
        } else {
            self.pretty.end_object(w)
        };
        self.depth -= 1;
        r
    }
    fn begin_object_key<W: ?Sized + Write>(&mut self, w: &mut W, first: bool) -> io::Result<()> {
        if !self.flat() {
            return self.pretty.begin_object_key(w, first);
        }
        if first {
            Ok(())
        } else {
            w.write_all(b", ")
        }
    }
    fn begin_object_value<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        if self.flat() {
            w.write_all(b": ")
        } else {
            self.pretty.begin_object_value(w)
        }
    }
    fn end_object_value<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        if self.flat() {
            Ok(())
        } else {
            self.pretty.end_object_value(w)
        }
    }
}
