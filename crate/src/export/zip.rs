//! A zip archive of stored (uncompressed) files, for downloads that are more than one file (OBJ
//! and its MTL). Deterministic: every entry is dated 1980-01-01 00:00, the zip epoch. No zip64, so
//! at most 4 GiB in all, far more than a browser can hand over.

/// CRC-32 (IEEE 802.3, reflected, as zip uses), table-driven.
pub(crate) fn crc32(bytes: &[u8]) -> u32 {
    const TABLE: [u32; 256] = {
        let mut table = [0u32; 256];
        let mut n = 0;
        while n < 256 {
            let mut c = n as u32;
            let mut k = 0;
            while k < 8 {
                c = if c & 1 != 0 {
                    0xEDB8_8320 ^ (c >> 1)
                } else {
                    c >> 1
                };
                k += 1;
            }
            table[n] = c;
            n += 1;
        }
        table
    };
    !bytes.iter().fold(!0u32, |c, &b| {
        TABLE[((c ^ b as u32) & 0xFF) as usize] ^ (c >> 8)
    })
}

/// DOS date of 1980-01-01 (day 1, month 1, year 0); the time is 00:00:00 (0).
const DOS_DATE: u16 = (1 << 5) | 1;
/// Version 2.0 of the format: enough for stored files.
const VERSION: u16 = 20;
/// General-purpose flag bit 11: names are UTF-8.
const UTF8_NAMES: u16 = 1 << 11;

/// A zip of `files` (name, contents), stored in that order. Returns `None` past 4 GiB.
pub fn stored(files: &[(&str, &[u8])]) -> Option<Vec<u8>> {
    let mut out: Vec<u8> = Vec::new();
    let mut central: Vec<u8> = Vec::new();
    let le16 = |v: &mut Vec<u8>, x: u16| v.extend_from_slice(&x.to_le_bytes());
    let le32 = |v: &mut Vec<u8>, x: u32| v.extend_from_slice(&x.to_le_bytes());
    for (name, data) in files {
        let offset = u32::try_from(out.len()).ok()?;
        let size = u32::try_from(data.len()).ok()?;
        let crc = crc32(data);
        let name_length = u16::try_from(name.len()).ok()?;
        // What the local header and the central directory entry both say, from the version
        // needed to the length of the extra field.
        let fields = |v: &mut Vec<u8>| {
            le16(v, VERSION);
            le16(v, UTF8_NAMES);
            le16(v, 0); // stored
            le16(v, 0); // time
            le16(v, DOS_DATE);
            le32(v, crc);
            le32(v, size);
            le32(v, size);
            le16(v, name_length);
            le16(v, 0); // no extra field
        };
        // Local file header.
        le32(&mut out, 0x0403_4b50);
        fields(&mut out);
        out.extend_from_slice(name.as_bytes());
        out.extend_from_slice(data);
        // Its central directory entry.
        le32(&mut central, 0x0201_4b50);
        le16(&mut central, VERSION); // made by: MS-DOS attributes, version 2.0
        fields(&mut central);
        le16(&mut central, 0); // comment
        le16(&mut central, 0); // disk
        le16(&mut central, 0); // internal attributes
        le32(&mut central, 0); // external attributes
        le32(&mut central, offset);
        central.extend_from_slice(name.as_bytes());
    }
    let directory_offset = u32::try_from(out.len()).ok()?;
    let directory_size = u32::try_from(central.len()).ok()?;
    let count = u16::try_from(files.len()).ok()?;
    out.extend_from_slice(&central);
    le32(&mut out, 0x0605_4b50);
    le16(&mut out, 0);
    le16(&mut out, 0);
    le16(&mut out, count);
    le16(&mut out, count);
    le32(&mut out, directory_size);
    le32(&mut out, directory_offset);
    le16(&mut out, 0); // no comment
    u32::try_from(out.len()).ok()?;
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc32_matches_the_standard_check_value() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        assert_eq!(crc32(b""), 0);
    }

    #[test]
    fn entries_are_stored_with_their_names_and_a_central_directory() {
        let zip = stored(&[("a.obj", b"v 0 0 0\n"), ("a.mtl", b"newmtl m\n")]).expect("small");
        assert_eq!(&zip[..4], b"PK\x03\x04");
        // Local header (30) + name (5) + data (8), twice over, then the directory.
        assert_eq!(&zip[30..35], b"a.obj");
        assert_eq!(&zip[35..43], b"v 0 0 0\n");
        let end = zip.len() - 22;
        assert_eq!(&zip[end..end + 4], b"PK\x05\x06");
        assert_eq!(u16::from_le_bytes([zip[end + 10], zip[end + 11]]), 2);
        let directory =
            u32::from_le_bytes([zip[end + 16], zip[end + 17], zip[end + 18], zip[end + 19]]);
        assert_eq!(
            &zip[directory as usize..directory as usize + 4],
            b"PK\x01\x02"
        );
        // The same input gives the same bytes.
        assert_eq!(
            stored(&[("a.obj", b"v 0 0 0\n"), ("a.mtl", b"newmtl m\n")]),
            Some(zip)
        );
    }
}
