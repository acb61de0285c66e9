//! The FMI boundary under hostile arguments: thousands of random calls (NULL pointers, counts
//! that cannot be, unknown value references, non-finite numbers, calls out of phase, FMU states
//! NULL, saved, restored and freed) return
//! fmi2OK or fmi2Error, never fmi2Fatal (a caught panic) and never a crash.

use super::*;
use crate::variables::REALS;
use fmi_sys::fmi2::fmi2Type_fmi2ModelExchange;
use std::ptr::{null, null_mut};

/// xorshift64*: reproducible random numbers without a dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn real(&mut self) -> f64 {
        let special = [
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.0,
            -0.0,
            1.0e300,
            -3.0e-6,
            2000.0,
            1.0e-4,
            f64::MIN_POSITIVE,
        ];
        match self.below(3) {
            0 => special[self.below(special.len() as u64) as usize],
            1 => (self.next() as i64 as f64) * 1.0e-24,
            _ => f64::from_bits(self.next()),
        }
    }
}

/// A resources directory of the hub-motor bearing with the integer network, its URI and GUID.
fn resources() -> (tempfile::TempDir, CString, CString) {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/hub_motor.toml"),
    )
    .unwrap();
    std::fs::write(dir.path().join(crate::RESOURCE_CONFIG), &text).unwrap();
    std::fs::write(dir.path().join(crate::RESOURCE_FILM), "int\n").unwrap();
    let uri = CString::new(format!("file://{}", dir.path().display())).unwrap();
    let guid = CString::new(crate::guid(&text, bearing_core::FilmKind::Int)).unwrap();
    (dir, uri, guid)
}

fn callbacks() -> fmi2CallbackFunctions {
    fmi2CallbackFunctions {
        logger: None,
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: null_mut(),
    }
}

#[test]
fn instantiate_refuses_bad_arguments_with_null() {
    let (_dir, uri, guid) = resources();
    let functions = callbacks();
    let name = c"fuzz";
    let bad_uri = c"file://elsewhere/x";
    let missing = c"file:///nonexistent/resources";
    let wrong_guid = c"{not-this}";
    let co_simulation = fmi2Type_fmi2CoSimulation;
    let cases: [(
        fmi2Type,
        fmi2String,
        fmi2String,
        *const fmi2CallbackFunctions,
    ); 6] = [
        (co_simulation, guid.as_ptr(), uri.as_ptr(), null()),
        (
            fmi2Type_fmi2ModelExchange,
            guid.as_ptr(),
            uri.as_ptr(),
            &functions,
        ),
        (co_simulation, guid.as_ptr(), null(), &functions),
        (co_simulation, guid.as_ptr(), bad_uri.as_ptr(), &functions),
        (co_simulation, guid.as_ptr(), missing.as_ptr(), &functions),
        (co_simulation, wrong_guid.as_ptr(), uri.as_ptr(), &functions),
    ];
    // SAFETY: every pointer is NULL, a NUL-terminated string or valid callbacks.
    unsafe {
        for (k, (kind, g, location, f)) in cases.into_iter().enumerate() {
            let c = fmi2Instantiate(name.as_ptr(), kind, g, location, f, 0, 0);
            assert!(c.is_null(), "case {k} was instantiated");
        }
        let c = fmi2Instantiate(
            null(),
            co_simulation,
            guid.as_ptr(),
            uri.as_ptr(),
            &functions,
            0,
            0,
        );
        assert!(!c.is_null(), "a NULL instance name is given a default");
        fmi2FreeInstance(c);
    }
}

#[test]
fn random_calls_return_ok_or_error_never_fatal() {
    let (_dir, uri, guid) = resources();
    let functions = callbacks();
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut counts = [0usize; 5];
    let mut steps = 0;
    // SAFETY: every non-NULL pointer passed points to a buffer of at least the count passed
    // with it (the importer's side of the contract); NULLs and impossible counts are the test.
    unsafe {
        let c = fmi2Instantiate(
            c"fuzz".as_ptr(),
            fmi2Type_fmi2CoSimulation,
            guid.as_ptr(),
            uri.as_ptr(),
            &functions,
            0,
            0,
        );
        assert!(!c.is_null());
        let mut refs = [0 as fmi2ValueReference; 8];
        let mut reals = [0.0; 8];
        let mut integers = [0 as fmi2Integer; 8];
        let mut state: fmi2FMUstate = null_mut();
        for _ in 0..20_000 {
            let n = rng.below(9) as usize;
            for r in refs.iter_mut() {
                *r = rng.below(REALS.len() as u64 + 4) as fmi2ValueReference;
            }
            for v in reals.iter_mut() {
                *v = rng.real();
            }
            for v in integers.iter_mut() {
                *v = rng.below(50) as i32 - 5;
            }
            // One call in eight: a NULL array with a count, or an impossible count.
            let (count, refs_ptr) = match rng.below(8) {
                0 => (n.max(1), null()),
                1 => (usize::MAX, null()),
                _ => (n, refs.as_ptr()),
            };
            let component = if rng.below(50) == 0 { null_mut() } else { c };
            let state_slot = if rng.below(4) == 0 {
                null_mut()
            } else {
                &mut state as *mut fmi2FMUstate
            };
            let status = match rng.below(15) {
                0..=3 => fmi2SetReal(component, refs_ptr, count, reals.as_ptr()),
                4 => fmi2GetReal(component, refs_ptr, count, reals.as_mut_ptr()),
                5 => fmi2SetInteger(component, refs_ptr, count, integers.as_ptr()),
                6 => fmi2GetInteger(component, refs_ptr, count, integers.as_mut_ptr()),
                7..=9 => fmi2DoStep(component, reals[0], reals[1], 0),
                10 => fmi2SetupExperiment(component, 0, 0.0, reals[0], 0, 0.0),
                11 => match rng.below(5) {
                    0 => fmi2EnterInitializationMode(component),
                    1 => fmi2ExitInitializationMode(component),
                    2 => fmi2Terminate(component),
                    3 => fmi2Reset(component),
                    _ => fmi2CancelStep(component),
                },
                12 => {
                    let out = if rng.below(2) == 0 {
                        null_mut()
                    } else {
                        reals.as_mut_ptr()
                    };
                    fmi2GetRealStatus(component, rng.below(5) as fmi2StatusKind, out)
                }
                13 => match rng.below(3) {
                    0 => fmi2GetFMUstate(component, state_slot),
                    1 => fmi2SetFMUstate(component, state),
                    _ => fmi2FreeFMUstate(component, state_slot),
                },
                _ => {
                    let names = [c"logAll".as_ptr(), c"nonsense".as_ptr(), null()];
                    let k = rng.below(4) as usize;
                    let list = if k == 0 { null() } else { names.as_ptr() };
                    fmi2SetDebugLogging(component, 1, k, list)
                }
            };
            assert!(status == OK || status == ERROR, "status {status}");
            counts[status as usize] += 1;
            // Now and then a well-formed start, so that random calls reach the stepping phase.
            if rng.below(200) == 0 {
                assert_eq!(fmi2Reset(c), OK);
                assert_eq!(fmi2EnterInitializationMode(c), OK);
                assert_eq!(fmi2SetReal(c, [6].as_ptr(), 1, [2000.0].as_ptr()), OK);
                assert_eq!(fmi2ExitInitializationMode(c), OK);
                assert_eq!(fmi2DoStep(c, 0.0, 1.0e-4, 0), OK);
                steps += 1;
            }
        }
        assert_eq!(fmi2FreeFMUstate(c, &mut state), OK);
        fmi2FreeInstance(c);
    }
    assert!(steps > 50, "{steps} well-formed starts");
    assert!(
        counts[OK as usize] > 1000 && counts[ERROR as usize] > 1000,
        "{counts:?}"
    );
}
