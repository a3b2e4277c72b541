//! CASPR import: pairing the bodies and cables files a user picked (and its trajectories file,
//! if picked too), converted by the core.

/// A CASPR model converted from the files a user picked.
#[derive(Debug, Clone, PartialEq)]
pub struct CasprImport {
    /// The model's name (the bodies file's name without `_bodies.xml`).
    pub name: String,
    /// The scenario JSON.
    pub json: String,
    /// The conversion notes.
    pub notes: Vec<String>,
    /// The cables file's cable sets, by id (one or more).
    pub sets: Vec<String>,
    /// The one imported.
    pub set: String,
}

/// From the files a user picked (name, text), the CASPR bodies and cables files (and the
/// trajectories file, if among them) converted by the core with the cable set `cable_set` (the
/// file's default for `None`); or a message saying what is missing or wrong.
pub fn caspr_pair(files: &[(String, Result<String, String>)], cable_set: Option<&str>) -> Result<CasprImport, String> {
    use cablenav::scenario::caspr;
    let mut bodies = None;
    let mut cables = None;
    let mut trajectories = None;
    for (name, text) in files {
        let text = text.as_ref().map_err(Clone::clone)?;
        match caspr::kind(text) {
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
    let fail = |e: cablenav::Error| format!("CASPR import: {e}");
    let out = caspr::model_to_json(&name, bodies, cables, trajectories.map(String::as_str), cable_set).map_err(fail)?;
    let sets = caspr::cable_sets(cables).map_err(fail)?;
    let set = cable_set.map(str::to_owned).or(sets.default).or_else(|| sets.ids.first().cloned()).unwrap_or_default();
    Ok(CasprImport { name, json: out.json, notes: out.notes, sets: sets.ids, set })
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
        let got = caspr_pair(&files, None).unwrap();
        assert_eq!(got.name, "NIST_RoboCrane");
        assert_eq!(Scenario::from_json(&got.json).unwrap().robot.cables.len(), 6);
        assert_eq!(got.sets.len(), 1);
        let e = caspr_pair(&[("a.xml".into(), Ok(bodies.to_string()))], None).unwrap_err();
        assert!(e.contains("both"), "{e}");
        let e = caspr_pair(&[("a.xml".into(), Err("could not read a.xml".into()))], None).unwrap_err();
        assert_eq!(e, "could not read a.xml");
        let broken = bodies.replace("SPATIAL_EULER_XYZ", "R_X");
        let e = caspr_pair(&[("b.xml".into(), Ok(broken)), ("c.xml".into(), Ok(cables.to_string()))], None).unwrap_err();
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
        let got = caspr_pair(&files, None).unwrap();
        let s = Scenario::from_json(&got.json).unwrap();
        assert_eq!(got.name, "CoGiRo");
        assert_eq!(s.trajectories.iter().filter(|t| t.knots.is_some()).count(), 4);
    }

    #[test]
    fn another_cable_set_is_picked_by_its_id() {
        let bodies = include_str!("../../../../shared/models/caspr/Example_spatial/Example_spatial_bodies.xml");
        let cables = include_str!("../../../../shared/models/caspr/Example_spatial/Example_spatial_cables.xml");
        let files = [("Example_spatial_bodies.xml".to_string(), Ok(bodies.to_string())), ("Example_spatial_cables.xml".to_string(), Ok(cables.to_string()))];
        let first = caspr_pair(&files, None).unwrap();
        assert_eq!((first.sets.len(), first.set.as_str()), (4, "basic_7_cables"));
        let cross = caspr_pair(&files, Some("cross_8_cables")).unwrap();
        assert_eq!((Scenario::from_json(&cross.json).unwrap().robot.cables.len(), cross.set.as_str()), (8, "cross_8_cables"));
        assert!(caspr_pair(&files, Some("nine")).unwrap_err().contains("cable_set"));
    }
}
