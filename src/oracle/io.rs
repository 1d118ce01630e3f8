//! Bounded line I/O: the JSON-lines loop, never storing more than one line's limit.

use super::{handle_line, MAX_LINE_BYTES};
use serde_json::json;
use std::io::{self, BufRead, BufReader, Read, Write};

/// One line read by [`read_line_bounded`].
#[derive(Debug, PartialEq, Eq)]
pub enum Line {
    /// A complete line (without its `\n`), at most the limit long.
    Text(Vec<u8>),
    /// A line longer than the limit: returned as soon as the limit is crossed, with the
    /// rest of the line still unread (skip it with [`skip_line`]).
    TooLong,
    /// End of input.
    Eof,
}

/// Reads one line of at most `limit` bytes. As soon as a line exceeds the limit it returns
/// [`Line::TooLong`], having stored nothing beyond the limit, and leaves the rest of the line
/// unread. The final line needs no `\n`.
pub fn read_line_bounded<R: BufRead>(reader: &mut R, limit: usize) -> io::Result<Line> {
    Ok(match read_line_bounded_keeping(reader, limit, false)? {
        Bounded::Text(line) => Line::Text(line),
        Bounded::TooLong(_) => Line::TooLong,
        Bounded::Eof => Line::Eof,
    })
}

/// Skips the rest of the current line (through its `\n`) in chunks, storing nothing.
pub fn skip_line<R: BufRead>(reader: &mut R) -> io::Result<()> {
    loop {
        let buf = match reader.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if buf.is_empty() {
            return Ok(());
        }
        match buf.iter().position(|&b| b == b'\n') {
            Some(i) => {
                reader.consume(i + 1);
                return Ok(());
            }
            None => {
                let n = buf.len();
                reader.consume(n);
            }
        }
    }
}

/// Bytes read from the input at a time by [`serve`]: a burst of requests this long is
/// answered with one write.
pub const READ_CHUNK_BYTES: usize = 64 * 1024;

/// The JSON-lines loop: one response line per request line, until end of input. An
/// over-long line is answered as soon as the limit is crossed, then skipped. Only I/O errors
/// (such as a closed output) end it early.
///
/// Responses are flushed whenever no complete request is waiting in the input buffer, i.e.
/// before the loop could block on a read: an interactive client gets every answer before it
/// has to send the next request, and a piped burst is answered in large writes instead of
/// one write per line. `writer` should therefore be buffered (`serve` adds no buffer of its
/// own on the output side).
pub fn serve<R: Read, W: Write>(reader: R, mut writer: W) -> io::Result<()> {
    let mut reader = BufReader::with_capacity(READ_CHUNK_BYTES, reader);
    loop {
        // the CR of a CRLF line end does not count against the limit
        let line = read_line_bounded_keeping(&mut reader, MAX_LINE_BYTES, true)?;
        let response = match &line {
            Bounded::Eof => return writer.flush(),
            Bounded::TooLong(start) => too_long(start),
            Bounded::Text(bytes) => match std::str::from_utf8(bytes.strip_suffix(b"\r").unwrap_or(bytes)) {
                Ok(s) => handle_line(s),
                Err(_) => json!({"ok": false, "error": "request line is not valid UTF-8"}).to_string(),
            },
        };
        writer.write_all(response.as_bytes())?;
        writer.write_all(b"\n")?;
        if let Bounded::TooLong(_) = line {
            writer.flush()?;
            skip_line(&mut reader)?;
        } else if !reader.buffer().contains(&b'\n') {
            writer.flush()?;
        }
    }
}

/// [`read_line_bounded`], keeping the start of an over-long line (its first `limit + 1`
/// bytes at most) so that its answer can carry the request's `id`; with `crlf`, the `\r`
/// of a `\r\n` line end is not counted.
enum Bounded {
    Text(Vec<u8>),
    TooLong(Vec<u8>),
    Eof,
}

fn read_line_bounded_keeping<R: BufRead>(reader: &mut R, limit: usize, crlf: bool) -> io::Result<Bounded> {
    let mut line = Vec::new();
    let mut seen_any = false;
    loop {
        let buf = match reader.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if buf.is_empty() {
            return Ok(if seen_any { Bounded::Text(line) } else { Bounded::Eof });
        }
        seen_any = true;
        let (chunk, found) = match buf.iter().position(|&b| b == b'\n') {
            Some(i) => (&buf[..i], Some(i)),
            None => (buf, None),
        };
        let len = line.len() + chunk.len();
        // with `crlf`, one byte past the limit is allowed when it is a `\r` (of a CRLF end,
        // or of the input's end): a longer line is known as soon as any other byte arrives
        let last = chunk.last().or(line.last());
        let allowed = if crlf && len == limit + 1 && last == Some(&b'\r') {
            limit + 1
        } else {
            limit
        };
        if len > allowed {
            // consume only what fits under the limit plus one byte: the line is too long
            let take = (limit + 1).saturating_sub(line.len()).min(chunk.len());
            line.extend_from_slice(&chunk[..take]);
            reader.consume(take);
            return Ok(Bounded::TooLong(line));
        }
        line.extend_from_slice(chunk);
        let used = found.map_or(buf.len(), |i| i + 1);
        reader.consume(used);
        if found.is_some() {
            return Ok(Bounded::Text(line));
        }
    }
}

/// The answer to an over-long line: with the request's `id` when the line starts with it
/// (`{"id": …, …`), else without one.
fn too_long(start: &[u8]) -> String {
    let error = format!("request line longer than {MAX_LINE_BYTES} bytes; it was skipped");
    match leading_id(start) {
        Some(id) => format!(
            "{{\"error\":{},\"id\":{id},\"ok\":false}}",
            serde_json::Value::String(error)
        ),
        None => json!({"ok": false, "error": error}).to_string(),
    }
}

/// The text of the `id` when `start` (the beginning of a request line) opens with
/// `{"id": <value>` followed by `,` or `}`: the value as the client wrote it (so a long
/// integer id is echoed as its own digits), or `None` when it cannot be read there.
fn leading_id(start: &[u8]) -> Option<&str> {
    let text = match std::str::from_utf8(start) {
        Ok(s) => s,
        // the limit may cut a multi-byte character: the id lies before it
        Err(e) => std::str::from_utf8(&start[..e.valid_up_to()]).ok()?,
    };
    let rest = text.trim_start().strip_prefix('{')?.trim_start();
    let rest = rest.strip_prefix("\"id\"")?.trim_start().strip_prefix(':')?;
    let mut values = serde_json::Deserializer::from_str(rest).into_iter::<&serde_json::value::RawValue>();
    let value = values.next()?.ok()?;
    let after = rest[values.byte_offset()..].trim_start();
    (after.starts_with(',') || after.starts_with('}')).then(|| value.get().trim())
}
