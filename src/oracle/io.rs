//! Bounded line I/O: the JSON-lines loop, never storing more than one line's limit.

use super::{handle_line, MAX_LINE_BYTES};
use serde_json::json;
use std::io::{self, BufRead, Write};

/// One line read by [`read_line_bounded`].
#[derive(Debug, PartialEq, Eq)]
pub enum Line {
    /// A complete line (without its `\n`), at most the limit long.
    Text(Vec<u8>),
    /// A line longer than the limit; its bytes were skipped, not stored.
    TooLong,
    /// End of input.
    Eof,
}

/// Reads one line of at most `limit` bytes. A longer line is skipped to its end in
/// chunks, so it never takes more memory than the limit. The final line needs no `\n`.
pub fn read_line_bounded<R: BufRead>(reader: &mut R, limit: usize) -> io::Result<Line> {
    let mut line = Vec::new();
    let mut too_long = false;
    let mut seen_any = false;
    loop {
        let buf = match reader.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if buf.is_empty() {
            return Ok(match (seen_any, too_long) {
                (false, _) => Line::Eof,
                (true, true) => Line::TooLong,
                (true, false) => Line::Text(line),
            });
        }
        seen_any = true;
        let (chunk, found) = match buf.iter().position(|&b| b == b'\n') {
            Some(i) => (&buf[..i], Some(i)),
            None => (buf, None),
        };
        if !too_long {
            if line.len() + chunk.len() > limit {
                too_long = true;
                line = Vec::new();
            } else {
                line.extend_from_slice(chunk);
            }
        }
        let used = found.map_or(buf.len(), |i| i + 1);
        reader.consume(used);
        if found.is_some() {
            return Ok(if too_long { Line::TooLong } else { Line::Text(line) });
        }
    }
}

/// The JSON-lines loop: one response line per request line, flushed after each, until end
/// of input. Only I/O errors (such as a closed output) end it early.
pub fn serve<R: BufRead, W: Write>(mut reader: R, mut writer: W) -> io::Result<()> {
    loop {
        let response = match read_line_bounded(&mut reader, MAX_LINE_BYTES)? {
            Line::Eof => return Ok(()),
            Line::TooLong => json!({
                "ok": false,
                "error": format!("request line longer than {MAX_LINE_BYTES} bytes; it was skipped")
            })
            .to_string(),
            Line::Text(bytes) => match String::from_utf8(bytes) {
                Ok(s) => handle_line(s.trim_end_matches('\r')),
                Err(_) => json!({"ok": false, "error": "request line is not valid UTF-8"}).to_string(),
            },
        };
        writer.write_all(response.as_bytes())?;
        writer.write_all(b"\n")?;
        writer.flush()?;
    }
}
