//! Tests of the trace formats. References: exact round trips (the formats are lossless by
//! construction), the location and kind of each error as defined in the module docs, and the
//! CRC property that every one- and two-bit error in a codeword shorter than 91 607 bits is
//! detected (Koopman, "32-bit cyclic redundancy codes for Internet applications", DSN 2002:
//! Hamming distance 4 for the IEEE 802.3 polynomial at those lengths).

use super::synthetic::Whirl;
use super::wire::{self, DecodeError, Header, HEADER_LEN};
use super::*;
use proptest::prelude::*;

fn meta() -> TraceMeta {
    TraceMeta {
        bearing: "hub_motor".into(),
        lubricant: "mineral_68".into(),
        sample_rate_hz: 10_000.0,
    }
}

fn whirl(tilt: bool, count: usize) -> Trace {
    Whirl {
        speed_rad_s: 2199.1,
        acceleration_rad_s2: 0.0,
        offset_m: [1.0e-6, -4.0e-6],
        radius_m: 2.5e-6,
        whirl_rad_s: 2.0 * std::f64::consts::PI * 350.0,
        tilt_amplitude_rad: tilt.then_some(1.0e-4),
    }
    .trace(meta(), count)
}

fn opts() -> ValidationOptions {
    ValidationOptions::default()
}

#[test]
fn binary_round_trip_is_exact_with_and_without_tilt() {
    for tilt in [false, true] {
        let trace = whirl(tilt, 257);
        let bytes = binary::encode(&trace).unwrap();
        let record = if tilt { 36 } else { 28 };
        assert_eq!(bytes.len(), HEADER_LEN + 257 * record);
        assert_eq!(binary::decode(&bytes, &opts()).unwrap(), trace);
    }
}

#[test]
fn csv_round_trip_is_exact_and_converts_back_to_identical_bytes() {
    for tilt in [false, true] {
        let trace = whirl(tilt, 100);
        let text = csv::render(&trace);
        let parsed = csv::parse(&text, &opts()).unwrap();
        assert_eq!(parsed, trace);
        assert_eq!(
            binary::encode(&parsed).unwrap(),
            binary::encode(&trace).unwrap()
        );
    }
}

fn csv_error(text: &str) -> TraceError {
    csv::parse(text, &opts()).unwrap_err()
}

const HEAD: &str = "# bearing: nu205\n# lubricant: oil\n# sample_rate_hz: 1000\ntime_s,speed_rad_s,x_m,y_m,vx_m_s,vy_m_s\n";

fn line_col(line: usize, column: usize, name: &str) -> Location {
    Location::Line {
        line,
        column: Some((column, name.to_string())),
    }
}

#[test]
fn csv_nan_and_infinity_name_line_and_column() {
    let e = csv_error(&format!("{HEAD}0,1,0,0,0,0\n0.001,1,NaN,0,0,0\n"));
    assert_eq!(e.location, line_col(6, 3, "x_m"));
    assert!(matches!(e.problem, Problem::NotFinite { .. }), "{e}");
    let e = csv_error(&format!("{HEAD}0,1,0,0,0,-inf\n"));
    assert_eq!(e.location, line_col(5, 6, "vy_m_s"));
    // 1e40 is finite in f64 but overflows the f32 the kinematics are stored in.
    let e = csv_error(&format!("{HEAD}0,1e40,0,0,0,0\n"));
    assert_eq!(e.location, line_col(5, 2, "speed_rad_s"));
    assert!(matches!(e.problem, Problem::NotFinite { .. }), "{e}");
    let e = csv_error(&format!("{HEAD}0,1,0,zero,0,0\n"));
    assert!(matches!(e.problem, Problem::NotANumber { .. }), "{e}");
    assert_eq!(
        e.to_string(),
        "line 5, column 4 (y_m): not a number: \"zero\""
    );
}

#[test]
fn csv_time_must_increase_without_gaps() {
    let e = csv_error(&format!("{HEAD}0,1,0,0,0,0\n0,1,0,0,0,0\n"));
    assert_eq!(e.location, line_col(6, 1, "time_s"));
    assert!(
        matches!(e.problem, Problem::NonIncreasingTime { .. }),
        "{e}"
    );
    // One lost sample at 1 kHz: a 2 ms step.
    let e = csv_error(&format!(
        "{HEAD}0,1,0,0,0,0\n0.001,1,0,0,0,0\n0.003,1,0,0,0,0\n"
    ));
    assert_eq!(e.location, line_col(7, 1, "time_s"));
    match e.problem {
        Problem::Gap {
            step_s, expected_s, ..
        } => {
            assert!((step_s - 0.002).abs() < 1e-12);
            assert!((expected_s - 0.001).abs() < 1e-15);
        }
        other => panic!("expected a gap, got {other}"),
    }
    // A 0.5 % jitter is inside the default 1 % tolerance.
    assert!(csv::parse(&format!("{HEAD}0,1,0,0,0,0\n0.001005,1,0,0,0,0\n"), &opts()).is_ok());
}

#[test]
fn csv_header_errors() {
    let e = csv_error("# bearing: nu205\n# lubricant: oil\ntime_s,speed_rad_s,x_m,y_m,vx_m_s,vy_m_s\n0,1,0,0,0,0\n");
    assert_eq!(
        e.location,
        Location::Line {
            line: 3,
            column: None
        }
    );
    assert!(e.to_string().contains("sample_rate_hz"), "{e}");
    let e = csv_error(
        "# bearing: nu205\n# lubricant: oil\n# sample_rate_hz: 1000\ntime,speed,x,y,vx,vy\n",
    );
    assert!(matches!(e.problem, Problem::BadHeader(_)), "{e}");
    assert_eq!(
        e.location,
        Location::Line {
            line: 4,
            column: None
        }
    );
    let e = csv_error("# bearing: nu205\n# lubricant: oil\n# sample_rate_hz: -5\ntime_s,speed_rad_s,x_m,y_m,vx_m_s,vy_m_s\n0,1,0,0,0,0\n");
    assert!(matches!(e.problem, Problem::BadMeta(_)), "{e}");
    let e = csv_error("# bearing: nu 205\n# lubricant: oil\n# sample_rate_hz: 5\ntime_s,speed_rad_s,x_m,y_m,vx_m_s,vy_m_s\n0,1,0,0,0,0\n");
    assert_eq!(
        e.location,
        Location::Line {
            line: 1,
            column: None
        }
    );
    let e = csv_error(&format!("{HEAD}0,1,0,0,0\n"));
    assert_eq!(
        e.problem,
        Problem::FieldCount {
            found: 5,
            expected: 6
        }
    );
    assert_eq!(csv_error(HEAD).problem, Problem::Empty);
    assert!(matches!(csv_error("").problem, Problem::BadHeader(_)));
}

fn decode_error(bytes: &[u8]) -> TraceError {
    binary::decode(bytes, &opts()).unwrap_err()
}

/// Re-seals a header after editing it, so that the check under test is the one that fires.
fn reseal(bytes: &mut [u8]) {
    let crc = crc32::crc32(&bytes[..60]);
    bytes[60..64].copy_from_slice(&crc.to_le_bytes());
}

#[test]
fn binary_layout_errors() {
    let good = binary::encode(&whirl(false, 10)).unwrap();

    let e = decode_error(&good[..40]);
    assert_eq!(
        e.problem,
        Problem::Binary(DecodeError::Truncated {
            expected: 64,
            actual: 40
        })
    );
    let e = decode_error(&good[..good.len() - 3]);
    assert!(
        matches!(e.problem, Problem::Binary(DecodeError::Truncated { .. })),
        "{e}"
    );
    // One whole record missing: a count mismatch, not a truncation.
    let e = decode_error(&good[..good.len() - 28]);
    assert_eq!(
        e.problem,
        Problem::Binary(DecodeError::CountMismatch {
            header: 10,
            found: 9
        })
    );

    let mut bad = good.clone();
    bad[0] = b'X';
    assert_eq!(
        decode_error(&bad).problem,
        Problem::Binary(DecodeError::BadMagic)
    );

    let mut bad = good.clone();
    bad[8] = 2;
    reseal(&mut bad);
    assert_eq!(
        decode_error(&bad).problem,
        Problem::Binary(DecodeError::UnsupportedVersion(2))
    );

    let mut bad = good.clone();
    bad[10] = 0x04;
    reseal(&mut bad);
    assert_eq!(
        decode_error(&bad).problem,
        Problem::Binary(DecodeError::UnknownFlags(4))
    );

    let mut bad = good.clone();
    bad[16..24].copy_from_slice(&f64::NAN.to_le_bytes());
    reseal(&mut bad);
    let e = decode_error(&bad);
    assert_eq!(e.problem, Problem::Binary(DecodeError::BadSampleRate));
    assert_eq!(e.location, Location::Byte(16));

    let mut bad = good.clone();
    bad[12] ^= 1;
    assert!(matches!(
        decode_error(&bad).problem,
        Problem::Binary(DecodeError::HeaderChecksum { .. })
    ));

    let mut bad = good.clone();
    let last = bad.len() - 1;
    bad[last] ^= 0x80;
    let e = decode_error(&bad);
    assert!(
        matches!(
            e.problem,
            Problem::Binary(DecodeError::PayloadChecksum { .. })
        ),
        "{e}"
    );
    assert_eq!(e.location, Location::Byte(56));

    let mut bad = good.clone();
    bad[24] = b' ';
    reseal(&mut bad);
    assert_eq!(
        decode_error(&bad).problem,
        Problem::Binary(DecodeError::BadIdentifier { which: "bearing" })
    );
}

#[test]
fn binary_content_errors_name_the_record_and_field() {
    let mut trace = whirl(true, 20);
    trace.samples[7].tilt_rad = Some([0.0, f32::INFINITY]);
    let e = decode_error(&binary::encode(&trace).unwrap());
    assert_eq!(
        e.location,
        Location::Record {
            index: 7,
            field: Some("tilt_y")
        }
    );
    let mut trace = whirl(false, 20);
    trace.samples[12].time_s = trace.samples[11].time_s;
    let e = decode_error(&binary::encode(&trace).unwrap());
    assert_eq!(
        e.location,
        Location::Record {
            index: 12,
            field: Some("time")
        }
    );
    assert!(matches!(e.problem, Problem::NonIncreasingTime { .. }));
}

#[test]
fn a_subnormal_sample_rate_is_refused_in_csv_and_binary() {
    // 4e-320 Hz is positive and finite, but its period 1/rate is infinite: every gap check
    // then compares with NaN, and a replay cannot time its steps.
    let text = HEAD.replace("sample_rate_hz: 1000", "sample_rate_hz: 4e-320") + "0,1,0,0,0,0\n";
    let e = csv_error(&text);
    assert_eq!(
        e.location,
        Location::Line {
            line: 3,
            column: None
        }
    );
    assert!(matches!(e.problem, Problem::BadMeta(_)), "{e}");
    assert!(e.to_string().contains("allowed 1e-3 ..= 1e7 Hz"), "{e}");
    let mut bytes = binary::encode(&whirl(false, 10)).unwrap();
    bytes[16..24].copy_from_slice(&4e-320f64.to_le_bytes());
    reseal(&mut bytes);
    let e = decode_error(&bytes);
    assert!(matches!(e.problem, Problem::BadMeta(_)), "{e}");
}

#[test]
fn streaming_header_and_records_agree_with_whole_file_decoding() {
    // The firmware path: parse the header, then decode and checksum record by record.
    let trace = whirl(true, 33);
    let bytes = binary::encode(&trace).unwrap();
    let header = Header::parse(bytes[..HEADER_LEN].try_into().unwrap()).unwrap();
    assert_eq!(header.count, 33);
    assert_eq!(wire::identifier_str(&header.bearing_id), "hub_motor");
    let mut check = wire::PayloadCheck::default();
    for (i, record) in bytes[HEADER_LEN..].chunks(header.record_len()).enumerate() {
        check.feed(record);
        assert_eq!(wire::decode_record(record, true).unwrap(), trace.samples[i]);
    }
    assert_eq!(check.verify(&header), Ok(()));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Random bytes, with or without a valid magic in front: an error or a valid trace, no panic.
    #[test]
    fn random_bytes_never_panic(mut bytes in proptest::collection::vec(any::<u8>(), 0..600), magic in any::<bool>()) {
        if magic && bytes.len() >= 8 {
            bytes[..8].copy_from_slice(&wire::MAGIC);
        }
        let _ = binary::decode(&bytes, &opts());
        let _ = csv::parse(&String::from_utf8_lossy(&bytes), &opts());
    }

    /// Every truncation of a valid file is refused.
    #[test]
    fn truncations_are_refused(count in 1usize..40, tilt in any::<bool>(), cut in 0.0f64..1.0) {
        let bytes = binary::encode(&whirl(tilt, count)).unwrap();
        let len = (cut * bytes.len() as f64) as usize;
        prop_assert!(len < bytes.len());
        prop_assert!(binary::decode(&bytes[..len], &opts()).is_err());
    }

    /// Every one- and two-bit flip of a valid file is detected (CRC-32 Hamming distance 4).
    #[test]
    fn bit_flips_are_detected(count in 1usize..40, tilt in any::<bool>(), a in any::<usize>(), b in any::<usize>()) {
        let bytes = binary::encode(&whirl(tilt, count)).unwrap();
        let bits = bytes.len() * 8;
        let mut one = bytes.clone();
        one[(a % bits) / 8] ^= 1 << (a % 8);
        prop_assert!(binary::decode(&one, &opts()).is_err());
        if a % bits != b % bits {
            let mut two = one.clone();
            two[(b % bits) / 8] ^= 1 << (b % 8);
            prop_assert!(binary::decode(&two, &opts()).is_err());
        }
    }

    /// CSV text built from the characters a CSV trace uses, scrambled: no panic.
    #[test]
    fn scrambled_csv_never_panics(chars in proptest::collection::vec(prop::sample::select(vec!['0','1','9','.','-','e',',','\n','#',':','n','a','i','f',' ']), 0..400)) {
        let body: String = chars.into_iter().collect();
        let _ = csv::parse(&format!("{HEAD}{body}"), &opts());
    }
}
