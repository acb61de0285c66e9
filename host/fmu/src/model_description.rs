//! modelDescription.xml (FMI 2.0 co-simulation) from the variable table.
//!
//! Inputs have start 0; outputs are `calculated` (by `fmi2ExitInitializationMode`, then by each
//! `fmi2DoStep`) and depend on every input and parameter; parameters are `exact`, their start
//! values those of the bearing file, written as the f32 the core uses, widened to f64 exactly.

use std::fmt::Write;

use bearing_core::{BearingDesign, FilmKind};

use crate::variables::{
    parameter_values, Causality, Variability, FIRST_OUTPUT, FIRST_PARAMETER, INTEGERS, REALS, UNITS,
};
use crate::MODEL_IDENTIFIER;

/// XML text with `&`, `<`, `>` and `"` escaped.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The modelDescription.xml of the bearing `design` named `model_name`, stepping with `film`,
/// with GUID `guid`.
pub fn model_description(
    model_name: &str,
    design: &BearingDesign,
    film: FilmKind,
    guid: &str,
) -> String {
    let (parameters, integers) = parameter_values(design, film);
    let mut x = String::new();
    // `write!` into a String cannot fail.
    let mut w = |s: String| x.push_str(&s);
    w(format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <fmiModelDescription fmiVersion=\"2.0\" modelName=\"{}\" guid=\"{}\"\n  \
         description=\"Lubricated cylindrical roller bearing (bearing-core): forces, moments, \
         stiffness and damping of the rollers on the inner race, film model {}\"\n  \
         generationTool=\"bearing fmu export {}\" variableNamingConvention=\"flat\" \
         numberOfEventIndicators=\"0\">\n",
        escape(model_name),
        escape(guid),
        film.name(),
        env!("CARGO_PKG_VERSION"),
    ));
    w(format!(
        "  <CoSimulation modelIdentifier=\"{MODEL_IDENTIFIER}\" \
         canHandleVariableCommunicationStepSize=\"true\" \
         canBeInstantiatedOnlyOncePerProcess=\"false\" canNotUseMemoryManagementFunctions=\"true\" \
         canGetAndSetFMUstate=\"true\" canSerializeFMUstate=\"false\" \
         providesDirectionalDerivative=\"false\"/>\n"
    ));
    w("  <UnitDefinitions>\n".into());
    for (name, exponents) in UNITS {
        let mut base = String::new();
        for (symbol, e) in ["kg", "m", "s", "rad"].iter().zip(exponents) {
            if e != 0 {
                let _ = write!(base, " {symbol}=\"{e}\"");
            }
        }
        w(format!(
            "    <Unit name=\"{}\"><BaseUnit{base}/></Unit>\n",
            escape(name)
        ));
    }
    w("  </UnitDefinitions>\n".into());
    w(
        "  <LogCategories>\n    <Category name=\"logStatusError\" description=\"Refused calls, \
       inputs and parameters\"/>\n    <Category name=\"logAll\" description=\"Every call\"/>\n  \
       </LogCategories>\n"
            .into(),
    );
    w("  <DefaultExperiment startTime=\"0\" stopTime=\"0.1\" stepSize=\"1e-4\"/>\n".into());
    w("  <ModelVariables>\n".into());
    for (vr, v) in REALS.iter().enumerate() {
        let (causality, variability, initial, start) = match (v.causality, v.variability) {
            (Causality::Input, _) => ("input", "continuous", "", " start=\"0\"".to_owned()),
            (Causality::Output, _) => {
                ("output", "continuous", " initial=\"calculated\"", "".into())
            }
            (Causality::Parameter, variability) => (
                "parameter",
                if variability == Variability::Tunable {
                    "tunable"
                } else {
                    "fixed"
                },
                " initial=\"exact\"",
                format!(" start=\"{:e}\"", parameters[vr - FIRST_PARAMETER]),
            ),
        };
        w(format!(
            "    <ScalarVariable name=\"{}\" valueReference=\"{vr}\" causality=\"{causality}\" \
             variability=\"{variability}\"{initial}\n      description=\"{}\">\n      \
             <Real unit=\"{}\"{start}/>\n    </ScalarVariable>\n",
            v.name,
            escape(v.description),
            escape(v.unit),
        ));
    }
    for (vr, (v, start)) in INTEGERS.iter().zip(integers).enumerate() {
        w(format!(
            "    <ScalarVariable name=\"{}\" valueReference=\"{vr}\" causality=\"parameter\" \
             variability=\"fixed\" initial=\"exact\"\n      description=\"{}\">\n      \
             <Integer min=\"{}\" max=\"{}\" start=\"{start}\"/>\n    </ScalarVariable>\n",
            v.name,
            escape(v.description),
            v.min,
            v.max,
        ));
    }
    w("  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n".into());
    // ModelStructure indices are 1-based positions in ModelVariables.
    for index in FIRST_OUTPUT + 1..=FIRST_PARAMETER {
        w(format!("      <Unknown index=\"{index}\"/>\n"));
    }
    w("    </Outputs>\n    <InitialUnknowns>\n".into());
    for index in FIRST_OUTPUT + 1..=FIRST_PARAMETER {
        w(format!("      <Unknown index=\"{index}\"/>\n"));
    }
    w("    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n".into());
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_variable_is_described_with_its_unit() {
        let xml = model_description("a <b> & \"c\"", &BearingDesign::NU205, FilmKind::F32, "{g}");
        assert!(xml.contains("modelName=\"a &lt;b&gt; &amp; &quot;c&quot;\""));
        assert_eq!(
            xml.matches("<ScalarVariable").count(),
            REALS.len() + INTEGERS.len()
        );
        assert_eq!(
            xml.matches("description=").count(),
            REALS.len() + INTEGERS.len() + 3
        );
        for v in REALS {
            assert!(xml.contains(&format!("name=\"{}\"", v.name)), "{}", v.name);
        }
        // The film model's start value is the code of F32.
        assert!(xml.contains("<Integer min=\"0\" max=\"3\" start=\"1\"/>"));
        // Pitch diameter of the NU 205 (f32 0.039 widened).
        assert!(xml.contains(&format!("start=\"{:e}\"", f64::from(0.039_f32))));
    }
}
