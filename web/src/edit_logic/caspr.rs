//! CASPR import: pairing the bodies and cables files a user picked (and its trajectories file,
//! if picked too), converted by the core.

/// From the files a user picked (name, text), the CASPR bodies and cables files (and the
/// trajectories file, if among them) converted by the core: the model's name (the bodies file's
/// name without `_bodies.xml`), the scenario JSON and the conversion notes; or a message saying
/// what is missing or wrong.
pub fn caspr_pair(files: Vec<(String, Result<String, String>)>) -> Result<(String, String, Vec<String>), String> {
    use cablenav::scenario::caspr;
    let mut bodies = None;
    let mut cables = None;
    let mut trajectories = None;
    for (name, text) in files {
        let text = text?;
        match caspr::kind(&text) {
            Some("bodies") => bodies = Some((name, text)),
            Some("cables") => cables = Some(text),
            Some("trajectories") => trajectories = Some(text),
            _ => {}
        }
    }
    let (Some((file, bodies)), Some(cables)) = (bodies, cables) else {
        return Err("choose both CASPR files of the model together: its bodies XML (<bodies_system>) and its cables XML (<cables>)".into());
    };
    let name = file.trim_end_matches(".xml").trim_end_matches("_bodies").to_string();
    let out = caspr::model_to_json(&name, &bodies, &cables, trajectories.as_deref()).map_err(|e| format!("CASPR import: {e}"))?;
    Ok((name, out.json, out.notes))
}

#[cfg(test)]
mod tests {
    
    
    use super::*;
    use cablenav::Scenario;
    

    #[test]
    fn caspr_files_are_paired_by_their_root() {
        let bodies = include_str!("../../../../shared/models/caspr/NIST_ROBOCRANE/NIST_RoboCrane_bodies.xml");
        let cables = include_str!("../../../../shared/models/caspr/NIST_ROBOCRANE/NIST_RoboCrane_cables.xml");
        let files = vec![
            ("NIST_RoboCrane_cables.xml".to_string(), Ok(cables.to_string())),
            ("NIST_RoboCrane_bodies.xml".to_string(), Ok(bodies.to_string())),
        ];
        let (name, json, _) = caspr_pair(files).unwrap();
        assert_eq!(name, "NIST_RoboCrane");
        assert_eq!(Scenario::from_json(&json).unwrap().robot.cables.len(), 6);
        let e = caspr_pair(vec![("a.xml".into(), Ok(bodies.to_string()))]).unwrap_err();
        assert!(e.contains("both"), "{e}");
        let e = caspr_pair(vec![("a.xml".into(), Err("could not read a.xml".into()))]).unwrap_err();
        assert_eq!(e, "could not read a.xml");
        let broken = bodies.replace("SPATIAL_EULER_XYZ", "R_X");
        let e = caspr_pair(vec![("b.xml".into(), Ok(broken)), ("c.xml".into(), Ok(cables.to_string()))]).unwrap_err();
        assert!(e.starts_with("CASPR import: bodies: line 6"), "{e}");
    }

    #[test]
    fn a_trajectories_file_picked_with_them_adds_its_timed_splines() {
        let model = |f: &str| match f {
            "bodies" => include_str!("../../../../shared/models/caspr/CoGiRo/CoGiRo_bodies.xml"),
            "cables" => include_str!("../../../../shared/models/caspr/CoGiRo/CoGiRo_cables.xml"),
            _ => include_str!("../../../../shared/models/caspr/CoGiRo/CoGiRo_trajectories.xml"),
        };
        let files = ["trajectories", "bodies", "cables"].map(|f| (format!("CoGiRo_{f}.xml"), Ok(model(f).to_string()))).to_vec();
        let (name, json, _) = caspr_pair(files).unwrap();
        let s = Scenario::from_json(&json).unwrap();
        assert_eq!(name, "CoGiRo");
        assert_eq!(s.trajectories.iter().filter(|t| t.knots.is_some()).count(), 4);
    }
}
