//! The layout of a certificate file: pretty JSON (two-space indent) down to depth
//! [`FLAT_BELOW`], and each deeper object or array on one line (`{"at": ["0"], "lhs": ["1"],
//! "rhs": ["1"]}`), as docs/certificates.md shows them. A sampled file is mostly such rows;
//! indenting every number of them made the files 2.6 times larger (72% blanks).

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
    /// `flat` on one line, else what the pretty formatter writes.
    fn either<W, F>(&mut self, w: &mut W, flat: &[u8], pretty: F) -> io::Result<()>
    where
        W: ?Sized + Write,
        F: FnOnce(&mut PrettyFormatter<'static>, &mut W) -> io::Result<()>,
    {
        if self.flat() {
            w.write_all(flat)
        } else {
            pretty(&mut self.pretty, w)
        }
    }
    fn open<W, F>(&mut self, w: &mut W, bracket: &[u8], pretty: F) -> io::Result<()>
    where
        W: ?Sized + Write,
        F: FnOnce(&mut PrettyFormatter<'static>, &mut W) -> io::Result<()>,
    {
        self.depth += 1;
        self.either(w, bracket, pretty)
    }
    fn close<W, F>(&mut self, w: &mut W, bracket: &[u8], pretty: F) -> io::Result<()>
    where
        W: ?Sized + Write,
        F: FnOnce(&mut PrettyFormatter<'static>, &mut W) -> io::Result<()>,
    {
        let r = self.either(w, bracket, pretty);
        self.depth -= 1;
        r
    }
    /// The separator before an element or a key on one line: `, ` after the first.
    fn comma(first: bool) -> &'static [u8] {
        if first {
            b""
        } else {
            b", "
        }
    }
}

impl Formatter for Layout {
    fn begin_array<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.open(w, b"[", |p, w| p.begin_array(w))
    }
    fn end_array<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.close(w, b"]", |p, w| p.end_array(w))
    }
    fn begin_array_value<W: ?Sized + Write>(&mut self, w: &mut W, first: bool) -> io::Result<()> {
        self.either(w, Self::comma(first), |p, w| p.begin_array_value(w, first))
    }
    fn end_array_value<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.either(w, b"", |p, w| p.end_array_value(w))
    }
    fn begin_object<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.open(w, b"{", |p, w| p.begin_object(w))
    }
    fn end_object<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.close(w, b"}", |p, w| p.end_object(w))
    }
    fn begin_object_key<W: ?Sized + Write>(&mut self, w: &mut W, first: bool) -> io::Result<()> {
        self.either(w, Self::comma(first), |p, w| p.begin_object_key(w, first))
    }
    fn begin_object_value<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.either(w, b": ", |p, w| p.begin_object_value(w))
    }
    fn end_object_value<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.either(w, b"", |p, w| p.end_object_value(w))
    }
}
