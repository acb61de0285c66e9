//! A minimal bearing firmware for a Cortex-M4F (STM32F405; QEMU's netduinoplus2): a SysTick
//! interrupt samples the shaft's kinematics at [`SAMPLE_RATE_HZ`] and pushes them through a
//! lock-free queue; the main loop pops each sample, steps the hub-motor bearing (film-coupled,
//! integer film network) and logs the bearing force and radial stiffness with defmt.
//!
//! Run: `cd core/examples/firmware-whirl && cargo run --release` (QEMU, `.cargo/config.toml`).
//! The shaft here whirls on a circle (x, y) = e·(cos ωt, sin ωt), an unbalance's synchronous
//! whirl; a real firmware reads its sensors in the interrupt instead. The program stops after
//! [`STEPS`] steps with exit code 0, or 1 if a sample was dropped or a step was refused.
#![no_std]
#![no_main]

use core::cell::RefCell;
use core::f32::consts::{PI, TAU};
use core::sync::atomic::{AtomicU32, Ordering};

use bearing_core::bearing::SETTLE_STEPS;
use bearing_core::{Bearing, BearingDesign, FilmKind, OperatingState};
use cortex_m::interrupt::{self, Mutex};
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::{entry, exception};
use cortex_m_semihosting::debug;
use defmt_semihosting as _;
use heapless::spsc::{Producer, Queue};

/// Core clock of the STM32F405 at full speed (RM0090 §6); SysTick counts it.
const CORE_CLOCK_HZ: u32 = 168_000_000;
/// Kinematics samples per second, one bearing step each.
const SAMPLE_RATE_HZ: u32 = 1_000;
const SAMPLE_PERIOD_S: f32 = 1.0 / SAMPLE_RATE_HZ as f32;
/// Steps before the program stops (a real firmware loops for ever).
const STEPS: u32 = 200;
/// Shaft speed: 3000 rpm, 20 samples per turn (the whirl's phase repeats after them).
const SAMPLES_PER_TURN: u32 = SAMPLE_RATE_HZ * 60 / 3000;
const SHAFT_SPEED_RAD_S: f32 = 3000.0 * PI / 30.0;
/// Whirl radius e (m); the whirl is synchronous, ω = shaft speed.
const WHIRL_RADIUS_M: f32 = 4.0e-6;

/// One kinematics sample of the inner race: displacement (m) and velocity (m/s).
#[derive(Clone, Copy)]
struct Sample {
    displacement_m: [f32; 2],
    velocity_m_s: [f32; 2],
}

/// Queue capacity: 7 samples (heapless keeps one slot free), 7 ms of slack for the main loop.
const QUEUE_SLOTS: usize = 8;
/// The interrupt's end of the queue, handed over once by `main`.
static PRODUCER: Mutex<RefCell<Option<Producer<'static, Sample, QUEUE_SLOTS>>>> =
    Mutex::new(RefCell::new(None));
/// Samples the interrupt could not queue (the main loop fell behind).
static DROPPED: AtomicU32 = AtomicU32::new(0);

/// The shaft's kinematics at sample `n`, t = n/rate: ωt = 2π·(n mod turn)/turn.
fn whirl(n: u32) -> Sample {
    let phase = (n % SAMPLES_PER_TURN) as f32 * (TAU / SAMPLES_PER_TURN as f32);
    let (sin, cos) = libm::sincosf(phase);
    let (e, w) = (WHIRL_RADIUS_M, SHAFT_SPEED_RAD_S);
    Sample {
        displacement_m: [e * cos, e * sin],
        velocity_m_s: [-e * w * sin, e * w * cos],
    }
}

/// The sampling interrupt. A real firmware reads its displacement probes (ADC, SPI) here.
#[exception]
fn SysTick() {
    static mut INDEX: u32 = 0;
    *INDEX = (*INDEX + 1) % SAMPLES_PER_TURN;
    let sample = whirl(*INDEX);
    interrupt::free(|cs| {
        let mut producer = PRODUCER.borrow(cs).borrow_mut();
        if !matches!(producer.as_mut().map(|p| p.enqueue(sample)), Some(Ok(()))) {
            DROPPED.fetch_add(1, Ordering::Relaxed);
        }
    });
}

// --- The bearing: every call of the core is in this section. ---

/// The hub-motor bearing (docs/physics.md §6.2, `configs/hub_motor.toml`) with the integer
/// film network and 10 slices per roller; the core integrates its cage angle.
struct HubMotor {
    bearing: Bearing<17, 10>,
}

impl HubMotor {
    /// The bearing, its warm start converged at `first` (`settle`, before the real-time loop:
    /// it renews the whole film table) so that every later step costs the same.
    fn new(first: &Sample) -> Option<Self> {
        let params = BearingDesign::HUB_MOTOR.params().ok()?;
        let mut bearing = Bearing::new(params, FilmKind::Int).ok()?;
        bearing.settle(&state(first)?, SETTLE_STEPS).ok()?;
        Some(Self { bearing })
    }

    /// One film-coupled step, one sample period on: force (N) and radial stiffness (N/m),
    /// `None` if the core refused the state.
    fn step(&mut self, sample: &Sample) -> Option<([f32; 2], [[f32; 2]; 2])> {
        let out = self.bearing.advance(&state(sample)?, SAMPLE_PERIOD_S).ok()?;
        Some((out.force_n, out.radial_stiffness_n_per_m()))
    }
}

/// The operating state of the inner race at `sample` (no tilt).
fn state(sample: &Sample) -> Option<OperatingState> {
    let (x, v, tilt) = (sample.displacement_m, sample.velocity_m_s, [0.0; 2]);
    OperatingState::new(x, v, tilt, SHAFT_SPEED_RAD_S).ok()
}

// --- The loop. ---

#[entry]
fn main() -> ! {
    static mut QUEUE: Queue<Sample, QUEUE_SLOTS> = Queue::new();
    let (producer, mut consumer) = QUEUE.split();
    interrupt::free(|cs| *PRODUCER.borrow(cs).borrow_mut() = Some(producer));
    let mut hub_motor = HubMotor::new(&whirl(0)).unwrap_or_else(|| exit(false));
    // A real firmware also sets up its clocks (168 MHz from the PLL) and sensors here.
    let mut syst = cortex_m::Peripherals::take()
        .unwrap_or_else(|| exit(false))
        .SYST;
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(CORE_CLOCK_HZ / SAMPLE_RATE_HZ - 1);
    syst.clear_current();
    syst.enable_interrupt();
    syst.enable_counter();
    defmt::info!("whirl {} m at {} rad/s", WHIRL_RADIUS_M, SHAFT_SPEED_RAD_S);

    let mut steps = 0u32;
    while steps < STEPS {
        let Some(sample) = consumer.dequeue() else {
            cortex_m::asm::wfi(); // until the next interrupt
            continue;
        };
        let Some(([fx, fy], [[kxx, _], [_, kyy]])) = hub_motor.step(&sample) else {
            exit(false)
        };
        // A real firmware hands the force and stiffness to its controller or observer here.
        defmt::info!(
            "step {}: F {} N, k_xx k_yy {} N/m",
            steps,
            [fx, fy],
            [kxx, kyy]
        );
        steps += 1;
    }
    let dropped = DROPPED.load(Ordering::Relaxed);
    defmt::info!("{=u32} steps, {=u32} samples dropped", steps, dropped);
    exit(dropped == 0)
}

/// Ends the QEMU run, exit code 0 or 1 (semihosting). A real firmware never returns.
fn exit(success: bool) -> ! {
    debug::exit(if success {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    loop {
        cortex_m::asm::wfi();
    }
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    exit(false)
}
