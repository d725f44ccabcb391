//! Reading a user's text file (a record or a preset) with the limits that keep a hostile file
//! from hanging or swelling the program: only regular files, at most [`MAX_BYTES`], UTF-8 checked
//! with the bad byte's line and column, and short quotes of bad lines.

use std::io::Read;
use std::path::Path;

/// The largest record, preset or lesson file read. The longest PEER records are a few megabytes; a file
/// past this is refused before it is read, so a mistaken path cannot take the machine's memory.
pub const MAX_BYTES: u64 = 64 * 1024 * 1024;

/// How many characters of an offending line or token an error message quotes.
pub const EXCERPT_CHARS: usize = 40;

/// Why a file was not read. The message is a sentence without the path: the caller names the
/// file (and knows whether it was a record or a preset).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum FileError {
    /// The system refused (missing, no permission, an I/O error).
    #[error("cannot read: {0}")]
    Read(String),
    /// A folder, a device or a pipe: reading one could block or never end.
    #[error("not a regular file (a folder, device or pipe); give a text file")]
    NotRegular,
    /// Past the size limit.
    #[error("larger than {} MiB, the most a record, preset or lesson file may hold", *.max_bytes as f64 / (1024.0 * 1024.0))]
    TooBig { max_bytes: u64 },
    /// Invalid UTF-8: the line and the byte within it (from 1), the offset in the file, the byte.
    #[error(
        "line {line}, byte {byte} (offset {offset} in the file): 0x{value:02X} is not valid UTF-8; save the file as UTF-8 text"
    )]
    NotUtf8 {
        line: usize,
        byte: usize,
        offset: usize,
        value: u8,
    },
}

/// Reads `path` as UTF-8 text, refusing devices, pipes and folders, files over [`MAX_BYTES`],
/// and invalid UTF-8 (named by line and byte).
pub fn read_text(path: &Path) -> Result<String, FileError> {
    read_text_limited(path, MAX_BYTES)
}

/// [`read_text`] with a given size limit.
pub fn read_text_limited(path: &Path, max_bytes: u64) -> Result<String, FileError> {
    let cannot = |e: std::io::Error| FileError::Read(e.to_string());
    let meta = std::fs::metadata(path).map_err(cannot)?;
    if !meta.is_file() {
        return Err(FileError::NotRegular);
    }
    if meta.len() > max_bytes {
        return Err(FileError::TooBig { max_bytes });
    }
    let file = std::fs::File::open(path).map_err(cannot)?;
    // Read at most one byte past the limit: a file that grows while being read is still bounded.
    let mut bytes = Vec::new();
    file.take(max_bytes + 1)
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > max_bytes {
        return Err(FileError::TooBig { max_bytes });
    }
    utf8(bytes)
}

/// The text of `bytes`, or an error naming the line and the byte (1-based, within the line) of
/// the first invalid UTF-8 sequence.
pub fn utf8(bytes: Vec<u8>) -> Result<String, FileError> {
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
        let line_start = bytes[..at]
            .iter()
            .rposition(|&b| b == b'\n')
            .map_or(0, |i| i + 1);
        FileError::NotUtf8 {
            line,
            byte: at - line_start + 1,
            offset: at,
            value: bytes[at],
        }
    })
}

/// ", line N" where a line is known: how the errors of files with lines (presets, records,
/// lessons) place it after the file's name.
pub fn at_line(line: Option<usize>) -> String {
    line.map(|l| format!(", line {l}")).unwrap_or_default()
}

/// At most [`EXCERPT_CHARS`] characters of `text`, with non-printing characters escaped and a
/// note of how much was left out.
pub fn excerpt(text: &str) -> String {
    let count = text.chars().count();
    let shown: String = text
        .chars()
        .take(EXCERPT_CHARS)
        .flat_map(|c| c.escape_debug())
        .collect();
    if count > EXCERPT_CHARS {
        format!("{shown}... ({count} characters)")
    } else {
        shown
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_invalid_byte_is_named_by_line_and_column() {
        let e = utf8(b"a = 1\nb = \xFF2\n".to_vec()).unwrap_err();
        assert_eq!(
            e,
            FileError::NotUtf8 {
                line: 2,
                byte: 5,
                offset: 10,
                value: 0xFF
            }
        );
        let text = e.to_string();
        assert!(text.contains("line 2, byte 5"), "{text}");
        assert!(text.contains("0xFF"), "{text}");
    }

    #[test]
    fn an_excerpt_of_a_long_token_is_short() {
        let long = "\0".repeat(1_000_000);
        let e = excerpt(&long);
        assert!(e.len() < 300, "{}", e.len());
        assert!(e.contains("1000000 characters"), "{e}");
    }
}
