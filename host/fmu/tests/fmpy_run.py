"""Import the bearing FMU in FMPy: validate it, simulate it driven by input tables, time doStep.

Usage: fmpy_run.py FMU CASE_IN.csv CASE_OUT.csv [CASE_IN.csv CASE_OUT.csv ...]

Each input table has a header `time,<input names>` and one row per communication point (times
k*h from 0, so FMPy's communication points fall on its rows and its linear interpolation returns
the row itself). fmpy.simulate_fmu drives the FMU with it (co-simulation, output interval h) and
its outputs are written to the matching output table, every value as the f64 FMPy read
(repr, which round-trips). The Rust test (tests/fmpy.rs) compares them with its own run of the
core. Then a direct loop over fmi2DoStep through FMPy's FMU2Slave is timed, and an input out of
the core's range must come back as fmi2Error with the field named in the log.
"""

import sys
import time

import numpy as np
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.validation import validate_fmu
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import FMU2Slave

fmu, cases = sys.argv[1], list(zip(sys.argv[2::2], sys.argv[3::2]))

problems = validate_fmu(fmu)
assert not problems, f"fmpy.validate_fmu: {problems}"
print("fmpy.validate_fmu: no problems")

md = read_model_description(fmu)
outputs = [v.name for v in md.modelVariables if v.causality == "output"]
vr = {v.name: v.valueReference for v in md.modelVariables}

for path_in, path_out in cases:
    signals = np.genfromtxt(path_in, delimiter=",", names=True)
    h = signals["time"][1] - signals["time"][0]
    stop = signals["time"][-1]
    start = time.perf_counter()
    result = simulate_fmu(fmu, stop_time=stop, output_interval=h, input=signals,
                          output=outputs, fmi_type="CoSimulation")
    seconds = time.perf_counter() - start
    assert len(result) == len(signals), (len(result), len(signals))
    with open(path_out, "w") as f:
        f.write(",".join(result.dtype.names) + "\n")
        for row in result:
            f.write(",".join(repr(float(v)) for v in row) + "\n")
    print(f"{path_in}: simulate_fmu {len(signals) - 1} steps in {seconds:.3f} s, "
          f"{1e6 * seconds / (len(signals) - 1):.1f} us per step")

    # fmi2DoStep alone, through FMPy's ctypes binding.
    unzipdir = extract(fmu)
    slave = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir,
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName="timing")
    slave.instantiate()
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    names = [n for n in signals.dtype.names if n != "time"]
    refs = [vr[n] for n in names]
    slave.setReal(refs, [float(signals[n][0]) for n in names])
    slave.exitInitializationMode()
    spent = 0.0
    for k in range(len(signals) - 1):
        slave.setReal(refs, [float(signals[n][k]) for n in names])
        t0 = time.perf_counter()
        slave.doStep(currentCommunicationPoint=k * h, communicationStepSize=h)
        spent += time.perf_counter() - t0
    print(f"{path_in}: fmi2DoStep through FMPy {1e6 * spent / (len(signals) - 1):.2f} us per call")

    # An input the core refuses: fmi2Error, the field named through the logger.
    slave.setReal([vr["displacement_x_m"]], [2.0e-3])
    try:
        slave.doStep(currentCommunicationPoint=(len(signals) - 1) * h, communicationStepSize=h)
        raise AssertionError("doStep accepted displacement_x_m = 2 mm")
    except FMICallException as e:
        print(f"refused as expected: status {e.status}")
    slave.terminate()
    slave.freeInstance()
