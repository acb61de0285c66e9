//! `bearing-hil-firmware`: the replay loop of the HIL harness on a Cortex-M4F.
//!
//! Run under `qemu-system-arm -machine netduinoplus2 -icount shift=0` with semihosting, in a
//! directory holding `trace.bin` (the binary trace format of `hil-sim/kernel/src/wire.rs`). The
//! firmware streams the trace record by record, checks its header and checksum with the same
//! decoder the host uses, steps the same kernel the host replay uses
//! (`hil-sim/kernel/src/kernel.rs`, which calls the core) and then the bearing's friction, counts
//! the instructions of every step and of its friction call apart, and writes `outputs.bin` (`hil-sim/kernel/src/outputs.rs`): the count and the outputs of
//! every step, then a trailer with the peak stack and the SysTick calibration. Logs go out as
//! defmt frames over semihosting stdout (`defmt-print -e <elf>` decodes them). The exit code
//! (semihosting SYS_EXIT_EXTENDED) is 0 on success and names the failure otherwise.

#![no_std]
#![no_main]

mod host_io;
mod profile;
mod stack;

use bearing_hil_kernel::{kernel, outputs, wire};
use bearing_m4_counter as counter;
use core::hint::black_box;
use cortex_m_rt::entry;
use cortex_m_semihosting::nr::open;
use defmt_semihosting as _;
use host_io::HostFile;
use outputs::{StepOutputs, Trailer, OUTPUT_RECORD_MAX};
use wire::{Header, HEADER_LEN, RECORD_LEN_MAX};

/// Why the replay stopped; the discriminant is the exit code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, defmt::Format)]
#[repr(u32)]
enum Failure {
    /// `trace.bin` cannot be opened or read.
    TraceIo = 2,
    /// The trace header is invalid (magic, version, flags, checksum, rate, identifiers).
    TraceHeader = 3,
    /// The file length does not match the header's count (truncated or count mismatch).
    TraceLength = 4,
    /// The records' checksum does not match.
    TraceChecksum = 5,
    /// The kernel refuses the trace's bearing or rate.
    Kernel = 6,
    /// A step failed.
    Step = 7,
    /// `outputs.bin` cannot be written.
    OutputIo = 8,
    /// SysTick counted nothing: the counts would be meaningless.
    CounterDead = 9,
    /// The core peripherals were already taken.
    Peripherals = 10,
    /// `film.txt` is missing or names no film model.
    FilmChoice = 11,
}

#[entry]
fn main() -> ! {
    let painted_top = stack::paint();
    let code = match run(painted_top) {
        Ok(()) => 0,
        Err(failure) => {
            defmt::error!("replay failed: {}", failure);
            failure as u32
        }
    };
    host_io::exit(code)
}

fn run(painted_top: usize) -> Result<(), Failure> {
    let mut peripherals = cortex_m::Peripherals::take().ok_or(Failure::Peripherals)?;
    counter::start(&mut peripherals.SYST);
    let calibration = counter::calibrate();
    defmt::info!(
        "calibration, 1000 nop: TIM2 {=u32} counts, SysTick {=u32} counts",
        calibration.instructions,
        calibration.systick
    );
    if calibration.instructions == 0 || calibration.systick == 0 {
        return Err(Failure::CounterDead);
    }

    let mut trace = HostFile::open(b"trace.bin\0", open::R_BINARY).map_err(|_| Failure::TraceIo)?;
    let file_len = trace.len().map_err(|_| Failure::TraceIo)?;
    let mut header_bytes = [0u8; HEADER_LEN];
    trace
        .read_exact(&mut header_bytes)
        .map_err(|_| Failure::TraceIo)?;
    let header = Header::parse(&header_bytes).map_err(|_| Failure::TraceHeader)?;
    header
        .check_length(file_len)
        .map_err(|_| Failure::TraceLength)?;
    let bearing = wire::identifier_str(&header.bearing_id);
    defmt::info!(
        "trace: bearing {=str}, lubricant {=str}, {=u32} samples at {=f64} Hz",
        bearing,
        wire::identifier_str(&header.lubricant_id),
        header.count,
        header.sample_rate_hz
    );
    let film = read_film_choice()?;
    let mut kernel = kernel::Kernel::new(
        bearing,
        wire::identifier_str(&header.lubricant_id),
        header.sample_rate_hz,
        film,
    )
    .map_err(|_| Failure::Kernel)?;
    defmt::info!("film model: {=str}", film.name());
    let rollers = kernel.rollers();

    let mut output =
        HostFile::open(b"outputs.bin\0", open::W_TRUNC_BINARY).map_err(|_| Failure::OutputIo)?;
    output
        .write_all(&outputs::encode_output_header(rollers as u16, header.count))
        .map_err(|_| Failure::OutputIo)?;

    // Stack used so far (setup), then repaint to measure the loop alone.
    let setup_lowest = stack::lowest_touched(painted_top);
    let loop_painted_top = stack::paint();

    let record_len = header.record_len();
    let mut record = [0u8; RECORD_LEN_MAX];
    let mut out = StepOutputs::default();
    let mut payload = wire::PayloadCheck::default();
    let (mut fewest, mut most) = (u32::MAX, 0u32);
    for index in 0..header.count {
        let bytes = record.get_mut(..record_len).ok_or(Failure::TraceLength)?;
        trace.read_exact(bytes).map_err(|_| Failure::TraceIo)?;
        payload.feed(bytes);
        let sample =
            wire::decode_record(bytes, header.has_tilt).map_err(|_| Failure::TraceLength)?;
        if index == 0 {
            // Converge the warm start before the first timed step, as the host replay does.
            kernel.prime(&sample);
        }

        let start = counter::now();
        let result = kernel.step(black_box(&sample), black_box(&mut out));
        let end = counter::now();
        let counts = counter::elapsed(start, end);
        if let Err(fault) = result {
            return Err(refused(index, fault));
        }
        if counts.instructions == 0 || counts.systick == 0 {
            return Err(Failure::CounterDead);
        }
        fewest = fewest.min(counts.instructions);
        most = most.max(counts.instructions);
        // The friction of the step, counted apart so that the step's count stays what it is,
        // and the record.
        friction_and_record(&mut kernel, &sample, &mut out, counts, &mut output, index)?;
    }
    payload
        .verify(&header)
        .map_err(|_| Failure::TraceChecksum)?;

    let loop_lowest = stack::lowest_touched(loop_painted_top);
    let lowest = setup_lowest.min(loop_lowest);
    let trailer = Trailer {
        status: 0,
        stack_bytes: (stack::stack_top() - lowest) as u32,
        loop_stack_bytes: (loop_painted_top + stack::CALLER_OFFSET - loop_lowest) as u32,
        calibration_instructions: calibration.instructions,
        calibration_systick: calibration.systick,
    };
    defmt::info!(
        "{=u32} steps, {=u32}..{=u32} instructions per step, peak stack {=u32} B (loop {=u32} B)",
        header.count,
        fewest,
        most,
        trailer.stack_bytes,
        trailer.loop_stack_bytes
    );
    output
        .write_all(&trailer.encode())
        .map_err(|_| Failure::OutputIo)?;
    // After the replay and its stack measurement, so that neither sees the profiling.
    profile::write_profile().map_err(|_| Failure::OutputIo)?;
    #[cfg(feature = "size-table")]
    profile::write_sizes().map_err(|_| Failure::OutputIo)?;
    Ok(())
}

/// After the step of sample `index`: the kernel's friction call, counted apart, then the
/// step's record (the step's `counts` and the friction's instructions) written to `output`. A
/// function of its own, not inlined into the replay loop, whose register allocation around the
/// timed step it would otherwise change (inlined, it added 1 to 9 instructions to the step's
/// count, depending on how it was written); the record's buffer lives in this frame too.
#[inline(never)]
fn friction_and_record(
    kernel: &mut kernel::Kernel,
    sample: &wire::Sample,
    out: &mut StepOutputs,
    counts: counter::Elapsed,
    output: &mut HostFile,
    index: u32,
) -> Result<(), Failure> {
    let start = counter::now();
    let friction = kernel.friction(black_box(sample), black_box(out));
    let end = counter::now();
    friction.map_err(|fault| refused(index, fault))?;
    let friction_instructions = counter::elapsed(start, end).instructions;
    if friction_instructions == 0 {
        return Err(Failure::CounterDead);
    }
    let record_counts = outputs::StepCounts {
        instructions: counts.instructions,
        systick: counts.systick,
        friction_instructions,
    };
    let mut encoded = [0u8; OUTPUT_RECORD_MAX];
    let len = outputs::encode_step(&record_counts, out, &mut encoded);
    output
        .write_all(encoded.get(..len).ok_or(Failure::OutputIo)?)
        .map_err(|_| Failure::OutputIo)
}

/// Logs the field the core refused at step `index`.
fn refused(index: u32, fault: kernel::KernelFault) -> Failure {
    let kernel::KernelFault::Rejected(error) = fault;
    defmt::error!(
        "step {=u32} refused by the core: field {=str}",
        index,
        error.field
    );
    Failure::Step
}

/// Reads the film model's name from `film.txt` (written by `hil-sim qemu`).
fn read_film_choice() -> Result<kernel::FilmKind, Failure> {
    let mut file =
        HostFile::open(b"film.txt\0", open::R_BINARY).map_err(|_| Failure::FilmChoice)?;
    let len = file.len().map_err(|_| Failure::FilmChoice)?;
    let mut name = [0u8; 16];
    let bytes = name.get_mut(..len).ok_or(Failure::FilmChoice)?;
    file.read_exact(bytes).map_err(|_| Failure::FilmChoice)?;
    kernel::FilmKind::from_name(bytes).ok_or(Failure::FilmChoice)
}

#[panic_handler]
fn panic(_info: &core::panic::PanicInfo) -> ! {
    host_io::exit(101)
}

#[defmt::panic_handler]
fn defmt_panic() -> ! {
    host_io::exit(101)
}
