//! A named test case and its JSON form, the corpus format of `corpus/paper/*.json`.

use serde::{Deserialize, Serialize};
use serde_json::{json, Value};

use super::Family;
use crate::input::{Input, Nesting, Role};

/// A named input with where it came from: a generated case, or one read from the corpus.
///
/// Its JSON is the corpus format:
///
/// ```json
/// {"name": "…", "description": "…", "source": "…",
///  "nesting": "auto" | "first-outer" | {"roles": ["outer", "hole", …]},
///  "rings": [[[x, y], …], …],
///  "family": "many-holes", "seed": 7, "expect": {…}}
/// ```
///
/// `family`, `seed` and `expect` are optional; other fields are ignored.
///
/// ```
/// use polytri_oracle::gen::{generate, Case, Family, Params};
/// let case = generate(Family::Star, 1, &Params::new(10));
/// let back = Case::from_json(&case.to_json()).unwrap();
/// assert_eq!(back.input, case.input);
/// assert_eq!(back.seed, Some(1));
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(into = "CaseJson", try_from = "CaseJson")]
pub struct Case {
    /// A name saying what the case is (`star-7-100`: family, seed, size).
    pub name: String,
    /// The family that generated it, if any.
    pub family: Option<Family>,
    /// The seed that generated it, if any.
    pub seed: Option<u64>,
    /// What the case exercises.
    pub description: String,
    /// Where it comes from (a paper figure, a generator, a bug report).
    pub source: String,
    /// The rings and the nesting convention.
    pub input: Input,
    /// What a triangulation must satisfy beyond validity (the corpus's `expect` object,
    /// such as `{"triangles": 28}`), kept as JSON.
    pub expect: Option<Value>,
}

impl Case {
    /// Reads a case from corpus JSON. A ring's repeated closing point is dropped.
    ///
    /// # Errors
    ///
    /// A message saying what is malformed.
    pub fn from_json(text: &str) -> Result<Case, String> {
        serde_json::from_str(text).map_err(|e| e.to_string())
    }

    /// The case as pretty-printed corpus JSON.
    pub fn to_json(&self) -> String {
        // Serialising plain data into a string cannot fail; fall back to the name only.
        serde_json::to_string_pretty(self)
            .unwrap_or_else(|e| format!("{{\"error\": {:?}}}", e.to_string()))
    }
}

/// The JSON shape of a [`Case`].
#[derive(Serialize, Deserialize)]
struct CaseJson {
    name: String,
    #[serde(default)]
    description: String,
    #[serde(default)]
    source: String,
    #[serde(default = "auto")]
    nesting: Value,
    rings: Vec<Vec<[f64; 2]>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    family: Option<Family>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    seed: Option<u64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    expect: Option<Value>,
}

fn auto() -> Value {
    json!("auto")
}

impl From<Case> for CaseJson {
    fn from(case: Case) -> CaseJson {
        let nesting = match &case.input.nesting {
            Nesting::Auto => json!("auto"),
            Nesting::FirstIsOuter => json!("first-outer"),
            Nesting::Roles(roles) => json!({ "roles": roles }),
        };
        CaseJson {
            name: case.name,
            description: case.description,
            source: case.source,
            nesting,
            rings: case.input.rings(),
            family: case.family,
            seed: case.seed,
            expect: case.expect,
        }
    }
}

impl TryFrom<CaseJson> for Case {
    type Error = String;

    fn try_from(json: CaseJson) -> Result<Case, String> {
        let nesting = match &json.nesting {
            Value::String(s) if s == "auto" => Nesting::Auto,
            Value::String(s) if s == "first-outer" => Nesting::FirstIsOuter,
            Value::Object(o) if o.contains_key("roles") => {
                let roles: Vec<Role> =
                    serde_json::from_value(o["roles"].clone()).map_err(|e| e.to_string())?;
                Nesting::Roles(roles)
            }
            other => {
                return Err(format!(
                    "nesting must be \"auto\", \"first-outer\" or {{\"roles\": […]}}, not {other}"
                ))
            }
        };
        let rings: Vec<Vec<[f64; 2]>> = json
            .rings
            .into_iter()
            .map(|mut ring| {
                if ring.len() > 1 && ring.first() == ring.last() {
                    ring.pop();
                }
                ring
            })
            .collect();
        Ok(Case {
            name: json.name,
            family: json.family,
            seed: json.seed,
            description: json.description,
            source: json.source,
            input: Input::from_rings(&rings, nesting),
            expect: json.expect,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_corpus_format() {
        let text = r#"{"name": "t", "description": "d", "source": "polytri",
            "nesting": "first-outer", "rings": [[[0,0],[4,0],[4,4],[0,0]], [[1,1],[2,1],[1,2]]],
            "expect": {"triangles": 5}, "unknown": true}"#;
        let case = Case::from_json(text).unwrap();
        assert_eq!(case.input.ring_starts, vec![0, 3]);
        assert_eq!(case.input.nesting, Nesting::FirstIsOuter);
        assert_eq!(case.expect, Some(json!({"triangles": 5})));
        let back = Case::from_json(&case.to_json()).unwrap();
        assert_eq!(back, case);
    }

    #[test]
    fn roles_round_trip() {
        let mut case = Case::from_json(r#"{"name": "r", "rings": [[[0,0],[1,0],[0,1]]]}"#).unwrap();
        case.input.nesting = Nesting::Roles(vec![Role::Outer]);
        assert!(case.to_json().contains("\"roles\""));
        assert_eq!(Case::from_json(&case.to_json()).unwrap(), case);
    }
}
