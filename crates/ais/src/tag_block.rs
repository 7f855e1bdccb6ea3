//! NMEA 4.0 tag blocks: `\c:1700000000,s:station*hh\` before a sentence.
//!
//! The AIS crates read the sentence, not the tag block; this module reads only
//! what the import needs from it: the checksum and the `c:` time (UNIX
//! seconds; a value above [`MILLISECONDS_ABOVE`] is taken as milliseconds, as
//! some receivers write it).

/// A `c:` value above this is in milliseconds, not seconds (1e11 s is the
/// year 5138).
pub const MILLISECONDS_ABOVE: f64 = 1e11;

/// What a line's tag block says.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TagBlock {
    /// The `c:` time, UNIX seconds, if the block has one.
    pub time_unix_s: Option<f64>,
}

/// Why a tag block was rejected.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TagBlockError {
    /// No closing `\`, no `*hh`, or a field that is not `key:value`.
    Malformed,
    /// The `*hh` checksum does not match the block's text.
    Checksum,
}

/// The XOR of the bytes of `text`: the NMEA checksum.
#[must_use]
pub fn nmea_checksum(text: &str) -> u8 {
    text.bytes().fold(0, |sum, byte| sum ^ byte)
}

/// Splits a line into its tag block (if it starts with `\`) and the rest.
///
/// # Errors
/// [`TagBlockError`] when the block is malformed or its checksum is wrong.
pub fn split_tag_block(line: &str) -> Result<(Option<TagBlock>, &str), TagBlockError> {
    let Some(after) = line.strip_prefix('\\') else {
        return Ok((None, line));
    };
    let Some((block, rest)) = after.split_once('\\') else {
        return Err(TagBlockError::Malformed);
    };
    let Some((body, checksum)) = block.rsplit_once('*') else {
        return Err(TagBlockError::Malformed);
    };
    if checksum.len() != 2 {
        return Err(TagBlockError::Malformed);
    }
    let expected = u8::from_str_radix(checksum, 16).map_err(|_| TagBlockError::Malformed)?;
    if nmea_checksum(body) != expected {
        return Err(TagBlockError::Checksum);
    }
    let mut tag = TagBlock::default();
    for field in body.split(',') {
        let Some((key, value)) = field.split_once(':') else {
            return Err(TagBlockError::Malformed);
        };
        if key == "c" {
            let time: f64 = value.parse().map_err(|_| TagBlockError::Malformed)?;
            if !(time.is_finite() && time >= 0.0) {
                return Err(TagBlockError::Malformed);
            }
            tag.time_unix_s = Some(if time > MILLISECONDS_ABOVE {
                time / 1000.0
            } else {
                time
            });
        }
    }
    Ok((Some(tag), rest))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn block(body: &str) -> String {
        format!("\\{body}*{:02X}\\!AIVDM,rest", nmea_checksum(body))
    }

    #[test]
    fn reads_the_time() {
        let line = block("s:station,c:1700000000");
        let (tag, rest) = split_tag_block(&line).unwrap();
        assert_eq!(tag.unwrap().time_unix_s, Some(1_700_000_000.0));
        assert_eq!(rest, "!AIVDM,rest");
        let line = block("c:1700000000500");
        let (tag, _) = split_tag_block(&line).unwrap();
        assert_eq!(tag.unwrap().time_unix_s, Some(1_700_000_000.5));
    }

    #[test]
    fn rejects_bad_blocks() {
        assert_eq!(split_tag_block("!AIVDM").unwrap(), (None, "!AIVDM"));
        assert_eq!(
            split_tag_block("\\c:1*00\\!AIVDM"),
            Err(TagBlockError::Checksum)
        );
        assert_eq!(split_tag_block("\\c:1*0"), Err(TagBlockError::Malformed));
        let line = block("c:soon");
        assert_eq!(split_tag_block(&line), Err(TagBlockError::Malformed));
        assert_eq!(split_tag_block("\\*é\\x"), Err(TagBlockError::Malformed));
    }
}
