//! Numbers as the editor reads and writes them: typed text to numbers (with messages for
//! what is not one), numbers to JSON (integers kept integral) and back to text.

use serde_json::{Number, Value};

/// A number as JSON: integers stay integers (`2`, not `2.0`), so edited files stay tidy.
pub fn number(x: f64) -> Value {
    if x.fract() == 0.0 && x.abs() < 9.0e15 {
        Value::Number(Number::from(x as i64))
    } else {
        Number::from_f64(x).map_or(Value::Null, Value::Number)
    }
}

/// A number as an editor shows it: the shortest text that reads back as the same value.
pub fn fmt_field(x: f64) -> String {
    if x == 0.0 {
        "0".to_string()
    } else {
        format!("{x}")
    }
}

/// A computed number rounded to 12 significant digits, so rounding noise (1.2000000000000002)
/// neither shows nor builds up when it is written back.
pub fn round12(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let text = format!("{x:.11e}");
    text.parse().unwrap_or(x)
}

/// Reads a number typed into a field: `Ok(None)` for an empty field, an error message for
/// anything that is not one finite number.
pub fn parse_number(text: &str) -> Result<Option<f64>, String> {
    let t = text.trim();
    if t.is_empty() {
        return Ok(None);
    }
    match t.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(Some(x)),
        Ok(_) => Err(format!("“{t}” is not a finite number")),
        Err(_) if t.contains(',') && !t.contains(' ') && t.matches(',').count() == 1 => {
            Err(format!("“{t}” is not a number (use a point for decimals: {})", t.replace(',', ".")))
        }
        Err(_) => Err(format!("“{t}” is not a number")),
    }
}

/// Reads "a number, or one number per cable": `5`, or `500, 500, 800` (commas or spaces).
pub fn parse_number_or_list(text: &str) -> Result<Option<Value>, String> {
    let parts: Vec<&str> = text.split([',', ' ', ';']).map(str::trim).filter(|s| !s.is_empty()).collect();
    match parts.as_slice() {
        [] => Ok(None),
        [one] => parse_number(one).map(|x| x.map(number)),
        many => {
            let mut xs = Vec::with_capacity(many.len());
            for p in many {
                xs.push(number(parse_number(p)?.ok_or("empty entry")?));
            }
            Ok(Some(Value::Array(xs)))
        }
    }
}

/// A number or a list of numbers as text (the inverse of [`parse_number_or_list`]).
pub fn fmt_number_or_list(v: &Value) -> String {
    match v {
        Value::Array(a) => a.iter().map(|x| x.as_f64().map_or_else(|| x.to_string(), fmt_field)).collect::<Vec<_>>().join(", "),
        Value::Number(n) => n.as_f64().map_or_else(String::new, fmt_field),
        Value::Null => String::new(),
        other => other.to_string(),
    }
}

/// Reads rows of numbers, one row a line (`x y z` or `x, y, z`), each of exactly `width`;
/// `integers` asks for whole numbers ≥ 0 (mesh vertex indices).
pub fn parse_rows(text: &str, width: usize, integers: bool) -> Result<Value, String> {
    let mut rows = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let parts: Vec<&str> = line.split([',', ' ', '\t', ';']).map(str::trim).filter(|s| !s.is_empty()).collect();
        if parts.is_empty() {
            continue;
        }
        if parts.len() != width {
            return Err(format!("line {}: expected {width} numbers, got {}", n + 1, parts.len()));
        }
        let mut row = Vec::with_capacity(width);
        for p in parts {
            let x = parse_number(p).map_err(|e| format!("line {}: {e}", n + 1))?.ok_or("empty")?;
            if integers && (x < 0.0 || x.fract() != 0.0) {
                return Err(format!("line {}: “{p}” is not a vertex index (a whole number from 0)", n + 1));
            }
            row.push(number(x));
        }
        rows.push(Value::Array(row));
    }
    Ok(Value::Array(rows))
}

/// Rows of numbers as text, one row a line (the inverse of [`parse_rows`]).
pub fn fmt_rows(v: Option<&Value>) -> String {
    let Some(Value::Array(rows)) = v else { return String::new() };
    rows.iter()
        .map(|r| match r {
            Value::Array(xs) => xs.iter().map(|x| x.as_f64().map_or_else(|| x.to_string(), fmt_field)).collect::<Vec<_>>().join(" "),
            other => other.to_string(),
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[cfg(test)]
mod tests {
    
    
    use super::*;
    
    use serde_json::json;

    #[test]
    fn numbers_parse_and_format() {
        assert_eq!(parse_number(" 2.5 "), Ok(Some(2.5)));
        assert_eq!(parse_number(""), Ok(None));
        assert!(parse_number("1,5").unwrap_err().contains("1.5"));
        assert!(parse_number("abc").is_err());
        assert!(parse_number("1e999").is_err());
        assert!(parse_number("NaN").is_err());
        assert_eq!(number(2.0), json!(2));
        assert_eq!(number(-0.25), json!(-0.25));
        assert_eq!(fmt_field(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(fmt_field(round12(0.1 + 0.2)), "0.3");
        assert_eq!(fmt_field(-0.0), "0");
        assert_eq!(parse_number_or_list("500, 500 800"), Ok(Some(json!([500, 500, 800]))));
        assert_eq!(parse_number_or_list("7"), Ok(Some(json!(7))));
        assert_eq!(parse_number_or_list(" "), Ok(None));
        assert!(parse_number_or_list("1, x").is_err());
        assert_eq!(fmt_number_or_list(&json!([1, 2.5])), "1, 2.5");
        let rows = parse_rows("0 0 0\n1, 0, 0\n\n0 1 0", 3, false).unwrap();
        assert_eq!(rows, json!([[0, 0, 0], [1, 0, 0], [0, 1, 0]]));
        assert_eq!(fmt_rows(Some(&rows)), "0 0 0\n1 0 0\n0 1 0");
        assert!(parse_rows("0 1", 3, false).unwrap_err().starts_with("line 1"));
        assert!(parse_rows("0 1 2.5", 3, true).is_err());
    }
}
