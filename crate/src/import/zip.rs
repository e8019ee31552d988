//! Reading a `.zip` (a vlab object or an L-Py model sent as one file): the central directory,
//! entries stored or deflated (inflated by `miniz_oxide`), each checked against its CRC-32.
//! Bounded: at most [`MAX_ENTRIES`] files and [`MAX_TOTAL`] bytes unpacked, so no archive can
//! exhaust memory; no zip64 (objects are small).

use super::ObjectFile;
use crate::export::zip::crc32;

/// The most files an archive may hold, and the most bytes they may unpack to.
pub const MAX_ENTRIES: usize = 4_096;
pub const MAX_TOTAL: usize = 64 << 20;

fn u16_at(b: &[u8], at: usize) -> Option<usize> {
    Some(u16::from_le_bytes(b.get(at..at + 2)?.try_into().ok()?) as usize)
}

fn u32_at(b: &[u8], at: usize) -> Option<usize> {
    Some(u32::from_le_bytes(b.get(at..at + 4)?.try_into().ok()?) as usize)
}

/// The files of a zip archive (folders and macOS's `__MACOSX/` copies left out), or why not.
pub fn unzip(bytes: &[u8]) -> Result<Vec<ObjectFile>, String> {
    let not_zip = || "not a zip archive (no end of central directory)".to_string();
    // The end of central directory record: the last `PK\5\6` within the comment's reach.
    let from = bytes.len().saturating_sub(22 + 65_535);
    let end = (from..bytes.len().saturating_sub(21))
        .rev()
        .find(|&i| bytes[i..].starts_with(&[0x50, 0x4b, 0x05, 0x06]))
        .ok_or_else(not_zip)?;
    let count = u16_at(bytes, end + 10).ok_or_else(not_zip)?;
    let mut at = u32_at(bytes, end + 16).ok_or_else(not_zip)?;
    if count == 0xFFFF || at == 0xFFFF_FFFF {
        return Err("a zip64 archive: Meristem reads only plain zip archives".into());
    }
    if count > MAX_ENTRIES {
        return Err(format!(
            "the archive holds {count} files; at most {MAX_ENTRIES} are read"
        ));
    }
    let mut files = Vec::new();
    let mut total = 0usize;
    for _ in 0..count {
        let broken = || "the archive's directory is broken".to_string();
        if !bytes
            .get(at..)
            .is_some_and(|b| b.starts_with(&[0x50, 0x4b, 0x01, 0x02]))
        {
            return Err(broken());
        }
        let method = u16_at(bytes, at + 10).ok_or_else(broken)?;
        let crc = u32_at(bytes, at + 16).ok_or_else(broken)? as u32;
        let packed = u32_at(bytes, at + 20).ok_or_else(broken)?;
        let size = u32_at(bytes, at + 24).ok_or_else(broken)?;
        let name_len = u16_at(bytes, at + 28).ok_or_else(broken)?;
        let extra_len = u16_at(bytes, at + 30).ok_or_else(broken)?;
        let comment_len = u16_at(bytes, at + 32).ok_or_else(broken)?;
        let local = u32_at(bytes, at + 42).ok_or_else(broken)?;
        let name_bytes = bytes
            .get(at.saturating_add(46)..at.saturating_add(46 + name_len))
            .ok_or_else(broken)?;
        let name = String::from_utf8_lossy(name_bytes).into_owned();
        at = at.saturating_add(46 + name_len + extra_len + comment_len);
        if name.ends_with('/') || name.starts_with("__MACOSX/") || name.contains("/__MACOSX/") {
            continue;
        }
        total = total.saturating_add(size);
        if total > MAX_TOTAL {
            return Err(format!(
                "the archive unpacks to more than {} MiB",
                MAX_TOTAL >> 20
            ));
        }
        let header = |k: usize| u16_at(bytes, local.checked_add(k)?);
        let data_at = local
            .saturating_add(30)
            .saturating_add(header(26).ok_or_else(broken)?)
            .saturating_add(header(28).ok_or_else(broken)?);
        let data = bytes
            .get(data_at..data_at.saturating_add(packed))
            .ok_or_else(|| format!("{name}: its data runs past the archive's end"))?;
        let data = match method {
            0 => data.to_vec(),
            8 => miniz_oxide::inflate::decompress_to_vec_with_limit(data, size)
                .map_err(|_| format!("{name}: its compressed data is broken"))?,
            m => {
                return Err(format!(
                    "{name}: compression method {m} (Meristem reads stored and deflated files)"
                ))
            }
        };
        if data.len() != size || crc32(&data) != crc {
            return Err(format!("{name}: its data does not match its checksum"));
        }
        files.push(ObjectFile { name, bytes: data });
    }
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stored_zip_reads_back() {
        let zip = crate::export::zip::stored(&[("obj/plant.l", b"Axiom: F\n"), ("obj/", b"")])
            .expect("zip");
        let files = unzip(&zip).expect("unzip");
        assert_eq!(files.len(), 1);
        assert_eq!(files[0].name, "obj/plant.l");
        assert_eq!(files[0].bytes, b"Axiom: F\n");
    }

    #[test]
    fn a_deflated_entry_inflates() {
        let text = b"F --> F[+F]F[-F]F\n".repeat(40);
        let packed = miniz_oxide::deflate::compress_to_vec(&text, 6);
        let mut zip = crate::export::zip::stored(&[("plant.l", &text)]).expect("zip");
        // Rewrite the single entry as deflated: method 8, sizes, then the packed data.
        let name_len = 7;
        let data_at = 30 + name_len;
        let central = data_at + text.len();
        let mut out = zip[..data_at].to_vec();
        out[8] = 8;
        out[18..22].copy_from_slice(&(packed.len() as u32).to_le_bytes());
        out.extend_from_slice(&packed);
        let mut dir = zip.split_off(central);
        dir[10] = 8;
        dir[20..24].copy_from_slice(&(packed.len() as u32).to_le_bytes());
        let dir_at = out.len() as u32;
        let eocd = dir.len() - 22;
        dir[eocd + 16..eocd + 20].copy_from_slice(&dir_at.to_le_bytes());
        out.extend_from_slice(&dir);
        let files = unzip(&out).expect("unzip");
        assert_eq!(files[0].bytes, text);
    }

    #[test]
    fn broken_archives_are_errors_not_panics() {
        assert!(unzip(b"").is_err());
        assert!(unzip(b"PK\x05\x06").is_err());
        let zip = crate::export::zip::stored(&[("a.l", b"Axiom: F")]).expect("zip");
        for cut in 0..zip.len() {
            let _ = unzip(&zip[..cut]);
            let mut bad = zip.clone();
            bad[cut] ^= 0xFF;
            let _ = unzip(&bad);
        }
    }
}
