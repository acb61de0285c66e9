//! The FMI 2.0 functions of a co-simulation FMU, exported from the shared library.
//!
//! The types are the standard's, from `fmi-sys` (bindgen over the standard's own headers, which
//! the crate ships); the functions are written here because no maintained crate exports
//! FMI 2.0 (`fmi-export` exports FMI 3.0 only, through a derive macro over fixed fields).
//!
//! No panic unwinds into the importer: every body runs under `catch_unwind`; a caught panic
//! is reported through the logger as `fmi2Fatal`, after which the instance answers every call
//! but `fmi2FreeInstance` with `fmi2Error`. Refused calls, arguments, inputs and parameters
//! are reported through the logger (category `logStatusError`) with `fmi2Error`; pointers are
//! checked for NULL and counts for size before use.

use std::ffi::{c_char, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

use fmi_sys::fmi2::{
    fmi2Boolean, fmi2Byte, fmi2CallbackFunctions, fmi2Component, fmi2FMUstate, fmi2Integer,
    fmi2Real, fmi2Status, fmi2StatusKind, fmi2StatusKind_fmi2LastSuccessfulTime,
    fmi2StatusKind_fmi2Terminated, fmi2Status_fmi2Error, fmi2Status_fmi2Fatal, fmi2Status_fmi2OK,
    fmi2String, fmi2Type, fmi2Type_fmi2CoSimulation, fmi2ValueReference,
};

use crate::instance::{Instance, Phase};
use crate::{path_of_file_uri, Resources};

const OK: fmi2Status = fmi2Status_fmi2OK;
const ERROR: fmi2Status = fmi2Status_fmi2Error;
const FATAL: fmi2Status = fmi2Status_fmi2Fatal;

/// What the importer's `fmi2Component` points to.
struct Component {
    name: CString,
    callbacks: fmi2CallbackFunctions,
    /// Debug logging (`logAll`): every successful call is logged too.
    logging_on: bool,
    /// A panic was caught: the instance's state is unknown.
    broken: bool,
    instance: Instance,
}

/// Send `message` to the importer's logger (as the argument of a `%s` format, so that no `%`
/// in it is read as a conversion).
fn log_to(
    callbacks: &fmi2CallbackFunctions,
    name: &CStr,
    status: fmi2Status,
    category: &CStr,
    message: &str,
) {
    if let Some(logger) = callbacks.logger {
        let text = CString::new(message.replace('\0', " ")).unwrap_or_default();
        // SAFETY: the logger is the importer's, called with NUL-terminated strings that
        // outlive the call and a format whose one conversion takes one string.
        unsafe {
            logger(
                callbacks.componentEnvironment,
                name.as_ptr(),
                status,
                category.as_ptr(),
                c"%s".as_ptr(),
                text.as_ptr(),
            )
        };
    }
}

impl Component {
    fn log(&self, status: fmi2Status, category: &CStr, message: &str) {
        log_to(&self.callbacks, &self.name, status, category, message);
    }

    /// The status of `result`, its error logged.
    fn report(&self, call: &str, result: Result<(), String>) -> fmi2Status {
        match result {
            Ok(()) => {
                if self.logging_on {
                    self.log(OK, c"logAll", call);
                }
                OK
            }
            Err(message) => {
                self.log(ERROR, c"logStatusError", &format!("{call}: {message}"));
                ERROR
            }
        }
    }
}

/// Run `body` on the component behind `c`, catching any panic.
fn with_component(
    c: fmi2Component,
    call: &str,
    body: impl FnOnce(&mut Component) -> Result<(), String>,
) -> fmi2Status {
    if c.is_null() {
        return ERROR;
    }
    // SAFETY: a non-NULL component is one `fmi2Instantiate` returned and `fmi2FreeInstance`
    // has not freed (the standard's contract with the importer).
    let component = unsafe { &mut *c.cast::<Component>() };
    if component.broken {
        component.log(
            ERROR,
            c"logStatusError",
            &format!("{call}: the instance failed fatally; only fmi2FreeInstance is allowed"),
        );
        return ERROR;
    }
    match catch_unwind(AssertUnwindSafe(|| body(&mut *component))) {
        Ok(result) => component.report(call, result),
        Err(_) => {
            component.broken = true;
            component.log(
                FATAL,
                c"logStatusFatal",
                &format!("{call}: internal error (a panic was caught at the FMI boundary)"),
            );
            FATAL
        }
    }
}

/// The `n` elements at `p` (empty when `n` is 0), or an error naming `argument` when `p` is
/// NULL or `n` elements cannot fit in memory.
///
/// # Safety
/// A non-NULL `p` must point to `n` readable elements that outlive the returned slice.
unsafe fn slice<'a, T>(p: *const T, n: usize, argument: &str) -> Result<&'a [T], String> {
    if n == 0 {
        return Ok(&[]);
    }
    if p.is_null() || n > isize::MAX as usize / std::mem::size_of::<T>().max(1) {
        return Err(format!("{argument} is NULL or its count {n} is impossible"));
    }
    // SAFETY: checked non-NULL and size above; the caller guarantees the rest.
    Ok(unsafe { std::slice::from_raw_parts(p, n) })
}

/// As [`slice`], writable.
///
/// # Safety
/// A non-NULL `p` must point to `n` writable elements that outlive the returned slice.
unsafe fn slice_mut<'a, T>(p: *mut T, n: usize, argument: &str) -> Result<&'a mut [T], String> {
    if n == 0 {
        return Ok(&mut []);
    }
    if p.is_null() || n > isize::MAX as usize / std::mem::size_of::<T>().max(1) {
        return Err(format!("{argument} is NULL or its count {n} is impossible"));
    }
    // SAFETY: checked non-NULL and size above; the caller guarantees the rest.
    Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
}

/// The text of a C string argument, `None` when NULL or not UTF-8.
///
/// # Safety
/// A non-NULL `s` must be NUL-terminated.
unsafe fn text<'a>(s: fmi2String) -> Option<&'a str> {
    if s.is_null() {
        return None;
    }
    // SAFETY: non-NULL and NUL-terminated by the caller's contract.
    unsafe { CStr::from_ptr(s) }.to_str().ok()
}

#[no_mangle]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    c"default".as_ptr()
}

#[no_mangle]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    c"2.0".as_ptr()
}

/// # Safety
/// FMI 2.0 contract: string arguments NUL-terminated or NULL, `functions` NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn fmi2Instantiate(
    instance_name: fmi2String,
    fmu_type: fmi2Type,
    fmu_guid: fmi2String,
    fmu_resource_location: fmi2String,
    functions: *const fmi2CallbackFunctions,
    _visible: fmi2Boolean,
    logging_on: fmi2Boolean,
) -> fmi2Component {
    if functions.is_null() {
        return std::ptr::null_mut();
    }
    let result = catch_unwind(|| {
        // SAFETY: non-NULL, and valid by the caller's contract.
        let callbacks = unsafe { *functions };
        // SAFETY: the caller's contract on string arguments.
        let name_text = unsafe { text(instance_name) }.unwrap_or("bearing");
        let name = CString::new(name_text).unwrap_or_default();
        let refuse = |message: String| {
            log_to(
                &callbacks,
                &name,
                ERROR,
                c"logStatusError",
                &format!("fmi2Instantiate: {message}"),
            );
            std::ptr::null_mut()
        };
        if fmu_type != fmi2Type_fmi2CoSimulation {
            return refuse(format!(
                "fmuType = {fmu_type} is not allowed: this FMU is co-simulation only \
                 (fmi2CoSimulation = {fmi2Type_fmi2CoSimulation})"
            ));
        }
        // SAFETY: the caller's contract on string arguments.
        let Some(location) = (unsafe { text(fmu_resource_location) }) else {
            return refuse("fmuResourceLocation is NULL or not UTF-8".into());
        };
        let Some(dir) = path_of_file_uri(location) else {
            return refuse(format!(
                "fmuResourceLocation = {location:?} is not a local file: URI"
            ));
        };
        let resources = match Resources::load(&dir) {
            Ok(r) => r,
            Err(e) => return refuse(e),
        };
        // SAFETY: the caller's contract on string arguments.
        let guid = unsafe { text(fmu_guid) }.unwrap_or("");
        if guid != resources.guid {
            return refuse(format!(
                "fmuGUID = {guid:?} is not the GUID of this FMU's resources ({})",
                resources.guid
            ));
        }
        let component = Box::new(Component {
            name,
            callbacks,
            logging_on: logging_on != 0,
            broken: false,
            instance: Instance::new(&resources.design, resources.film),
        });
        Box::into_raw(component).cast()
    });
    result.unwrap_or(std::ptr::null_mut())
}

/// # Safety
/// `c` NULL or returned by `fmi2Instantiate` and not yet freed.
#[no_mangle]
pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
    if !c.is_null() {
        // SAFETY: created by `Box::into_raw` in `fmi2Instantiate`, freed once.
        drop(unsafe { Box::from_raw(c.cast::<Component>()) });
    }
}

/// # Safety
/// FMI 2.0 contract on `c` and `categories`.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: fmi2Component,
    logging_on: fmi2Boolean,
    n_categories: usize,
    categories: *const fmi2String,
) -> fmi2Status {
    with_component(c, "fmi2SetDebugLogging", |comp| {
        // SAFETY: the caller's contract on `categories`.
        let names = unsafe { slice(categories, n_categories, "categories") }?;
        for &name in names {
            // SAFETY: the caller's contract on each category string.
            match unsafe { text(name) } {
                Some("logStatusError" | "logAll") => {}
                other => {
                    return Err(format!(
                        "category {other:?} is not allowed: logStatusError or logAll"
                    ))
                }
            }
        }
        comp.logging_on = logging_on != 0;
        Ok(())
    })
}

/// # Safety
/// FMI 2.0 contract on `c`.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: fmi2Component,
    _tolerance_defined: fmi2Boolean,
    _tolerance: fmi2Real,
    start_time: fmi2Real,
    _stop_time_defined: fmi2Boolean,
    _stop_time: fmi2Real,
) -> fmi2Status {
    with_component(c, "fmi2SetupExperiment", |comp| {
        comp.instance.setup_experiment(start_time)
    })
}

macro_rules! phase_call {
    ($name:ident, $method:ident) => {
        /// # Safety
        /// FMI 2.0 contract on `c`.
        #[no_mangle]
        pub unsafe extern "C" fn $name(c: fmi2Component) -> fmi2Status {
            with_component(c, stringify!($name), |comp| comp.instance.$method())
        }
    };
}

phase_call!(fmi2EnterInitializationMode, enter_initialization);
phase_call!(fmi2ExitInitializationMode, exit_initialization);
phase_call!(fmi2Terminate, terminate);

/// # Safety
/// FMI 2.0 contract on `c`.
#[no_mangle]
pub unsafe extern "C" fn fmi2Reset(c: fmi2Component) -> fmi2Status {
    with_component(c, "fmi2Reset", |comp| {
        comp.instance.reset();
        Ok(())
    })
}

/// # Safety
/// FMI 2.0 contract on `c`, `vr` (`nvr` elements) and `value` (`nvr` elements).
#[no_mangle]
pub unsafe extern "C" fn fmi2GetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Real,
) -> fmi2Status {
    with_component(c, "fmi2GetReal", |comp| {
        // SAFETY: the caller's contract on `vr` and `value`.
        let (refs, out) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        for (&r, slot) in refs.iter().zip(out.iter_mut()) {
            *slot = comp.instance.real(r)?;
        }
        Ok(())
    })
}

/// # Safety
/// FMI 2.0 contract on `c`, `vr` and `value`.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Integer,
) -> fmi2Status {
    with_component(c, "fmi2GetInteger", |comp| {
        // SAFETY: the caller's contract on `vr` and `value`.
        let (refs, out) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        for (&r, slot) in refs.iter().zip(out.iter_mut()) {
            *slot = comp.instance.integer(r)?;
        }
        Ok(())
    })
}

/// # Safety
/// FMI 2.0 contract on `c`, `vr` and `value`.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Real,
) -> fmi2Status {
    with_component(c, "fmi2SetReal", |comp| {
        // SAFETY: the caller's contract on `vr` and `value`.
        let (refs, values) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        for (&r, &v) in refs.iter().zip(values) {
            comp.instance.set_real(r, v)?;
        }
        Ok(())
    })
}

/// # Safety
/// FMI 2.0 contract on `c`, `vr` and `value`.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Integer,
) -> fmi2Status {
    with_component(c, "fmi2SetInteger", |comp| {
        // SAFETY: the caller's contract on `vr` and `value`.
        let (refs, values) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        for (&r, &v) in refs.iter().zip(values) {
            comp.instance.set_integer(r, v)?;
        }
        Ok(())
    })
}

/// Accessors of a type the FMU has no variables of: empty requests succeed, others are refused.
macro_rules! no_variables {
    ($name:ident, $value:ty, $kind:literal) => {
        /// # Safety
        /// FMI 2.0 contract on `c`.
        #[no_mangle]
        pub unsafe extern "C" fn $name(
            c: fmi2Component,
            _vr: *const fmi2ValueReference,
            nvr: usize,
            _value: $value,
        ) -> fmi2Status {
            with_component(c, stringify!($name), |_| match nvr {
                0 => Ok(()),
                _ => Err(format!("this FMU has no {} variables", $kind)),
            })
        }
    };
}

no_variables!(fmi2GetBoolean, *mut fmi2Boolean, "Boolean");
no_variables!(fmi2SetBoolean, *const fmi2Boolean, "Boolean");
no_variables!(fmi2GetString, *mut fmi2String, "String");
no_variables!(fmi2SetString, *const fmi2String, "String");

/// Calls for capabilities modelDescription.xml declares absent.
macro_rules! unsupported {
    ($name:ident, $why:literal, ($($arg:ident: $ty:ty),*)) => {
        /// # Safety
        /// FMI 2.0 contract on `c`.
        #[no_mangle]
        pub unsafe extern "C" fn $name(c: fmi2Component, $($arg: $ty),*) -> fmi2Status {
            $(let _ = $arg;)*
            with_component(c, stringify!($name), |_| Err($why.into()))
        }
    };
}

unsupported!(fmi2SerializedFMUstateSize, "canSerializeFMUstate is false",
    (s: fmi2FMUstate, size: *mut usize));
unsupported!(fmi2SerializeFMUstate, "canSerializeFMUstate is false",
    (s: fmi2FMUstate, bytes: *mut fmi2Byte, size: usize));
unsupported!(fmi2DeSerializeFMUstate, "canSerializeFMUstate is false",
    (bytes: *const fmi2Byte, size: usize, s: *mut fmi2FMUstate));
unsupported!(fmi2GetDirectionalDerivative, "providesDirectionalDerivative is false",
    (unknowns: *const fmi2ValueReference, n_unknown: usize, knowns: *const fmi2ValueReference,
     n_known: usize, dv_known: *const fmi2Real, dv_unknown: *mut fmi2Real));
unsupported!(fmi2SetRealInputDerivatives, "canInterpolateInputs is false",
    (vr: *const fmi2ValueReference, nvr: usize, order: *const fmi2Integer, value: *const fmi2Real));
unsupported!(fmi2GetRealOutputDerivatives, "maxOutputDerivativeOrder is 0",
    (vr: *const fmi2ValueReference, nvr: usize, order: *const fmi2Integer, value: *mut fmi2Real));
unsupported!(
    fmi2CancelStep,
    "fmi2DoStep always completes before it returns",
    ()
);
unsupported!(fmi2GetStatus, "fmi2DoStep always completes before it returns",
    (s: fmi2StatusKind, value: *mut fmi2Status));
unsupported!(fmi2GetIntegerStatus, "no Integer status is defined",
    (s: fmi2StatusKind, value: *mut fmi2Integer));
unsupported!(fmi2GetStringStatus, "fmi2DoStep always completes before it returns",
    (s: fmi2StatusKind, value: *mut fmi2String));

/// `fmi2GetFMUstate`: a copy of the instance's state, into `*state` when it holds one from an
/// earlier call, else newly allocated.
///
/// # Safety
/// FMI 2.0 contract on `c`; `state` NULL or pointing to NULL or to a state of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetFMUstate(c: fmi2Component, state: *mut fmi2FMUstate) -> fmi2Status {
    with_component(c, "fmi2GetFMUstate", |comp| {
        // SAFETY: the caller's contract on `state`.
        let [slot] = (unsafe { slice_mut(state, 1, "FMUstate") })? else {
            return Err("FMUstate is NULL".into());
        };
        let snapshot = comp.instance.snapshot();
        if slot.is_null() {
            *slot = Box::into_raw(Box::new(snapshot)).cast();
        } else {
            // SAFETY: a non-NULL state is one this function allocated and has not freed.
            unsafe { *slot.cast::<Instance>() = snapshot };
        }
        Ok(())
    })
}

/// `fmi2SetFMUstate`: the instance's state becomes a copy of `state`.
///
/// # Safety
/// FMI 2.0 contract on `c`; `state` NULL or a state of this library not yet freed.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetFMUstate(c: fmi2Component, state: fmi2FMUstate) -> fmi2Status {
    with_component(c, "fmi2SetFMUstate", |comp| {
        if state.is_null() {
            return Err("FMUstate is NULL".into());
        }
        // SAFETY: a non-NULL state is one `fmi2GetFMUstate` allocated and has not freed.
        comp.instance = unsafe { &*state.cast::<Instance>() }.snapshot();
        Ok(())
    })
}

/// `fmi2FreeFMUstate`: free `*state` (nothing when NULL) and set it to NULL.
///
/// # Safety
/// FMI 2.0 contract on `c`; `state` NULL or pointing to NULL or to a state of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2FreeFMUstate(
    c: fmi2Component,
    state: *mut fmi2FMUstate,
) -> fmi2Status {
    with_component(c, "fmi2FreeFMUstate", |_| {
        // SAFETY: the caller's contract on `state`.
        let [slot] = (unsafe { slice_mut(state, 1, "FMUstate") })? else {
            return Err("FMUstate is NULL".into());
        };
        if !slot.is_null() {
            // SAFETY: allocated by `Box::into_raw` in `fmi2GetFMUstate`, freed once.
            drop(unsafe { Box::from_raw(slot.cast::<Instance>()) });
            *slot = std::ptr::null_mut();
        }
        Ok(())
    })
}

/// # Safety
/// FMI 2.0 contract on `c`.
#[no_mangle]
pub unsafe extern "C" fn fmi2DoStep(
    c: fmi2Component,
    current_communication_point: fmi2Real,
    communication_step_size: fmi2Real,
    _no_set_fmu_state_prior_to_current_point: fmi2Boolean,
) -> fmi2Status {
    with_component(c, "fmi2DoStep", |comp| {
        comp.instance
            .do_step(current_communication_point, communication_step_size)
    })
}

/// # Safety
/// FMI 2.0 contract on `c` and `value`.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Real,
) -> fmi2Status {
    with_component(c, "fmi2GetRealStatus", |comp| {
        // SAFETY: the caller's contract on `value`.
        let [slot] = (unsafe { slice_mut(value, 1, "value") })? else {
            return Err("value is NULL".into());
        };
        if s != fmi2StatusKind_fmi2LastSuccessfulTime {
            return Err(format!(
                "status kind {s} is not allowed: fmi2LastSuccessfulTime only"
            ));
        }
        *slot = comp.instance.time_s();
        Ok(())
    })
}

/// # Safety
/// FMI 2.0 contract on `c` and `value`.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    with_component(c, "fmi2GetBooleanStatus", |comp| {
        // SAFETY: the caller's contract on `value`.
        let [slot] = (unsafe { slice_mut(value, 1, "value") })? else {
            return Err("value is NULL".into());
        };
        if s != fmi2StatusKind_fmi2Terminated {
            return Err(format!(
                "status kind {s} is not allowed: fmi2Terminated only"
            ));
        }
        *slot = fmi2Boolean::from(comp.instance.phase() == Phase::Terminated);
        Ok(())
    })
}

#[cfg(test)]
mod tests;
