//! `TestApp` methods for the models and jobs endpoints, and helpers for their tests.

use std::time::Duration;

use reqwest::multipart::{Form, Part};
use reqwest::Response;
use serde_json::Value;

use crate::app::TestApp;

/// A multipart upload form: the bundle as a file part named `bundle`, then text parts.
pub fn upload_form(bundle: Vec<u8>, file_name: &str, fields: &[(&str, &str)]) -> Form {
    let part = Part::bytes(bundle).file_name(file_name.to_string()).mime_str("application/zip").expect("mime");
    let mut form = Form::new().part("bundle", part);
    for (k, v) in fields {
        form = form.text(k.to_string(), v.to_string());
    }
    form
}

impl TestApp {
    /// `POST /api/models` with any form.
    pub async fn post_model_form(&self, form: Form) -> Response {
        self.client.post(self.url("/api/models")).multipart(form).send().await.expect("request")
    }

    /// `POST /api/models`: a new model from a bundle zip.
    pub async fn upload_model(&self, bundle: Vec<u8>, file_name: &str, fields: &[(&str, &str)]) -> Response {
        self.post_model_form(upload_form(bundle, file_name, fields)).await
    }

    /// `POST /api/models/{id}/versions` with any form.
    pub async fn post_version_form(&self, model_id: &str, form: Form) -> Response {
        self.client.post(self.url(&format!("/api/models/{model_id}/versions"))).multipart(form).send().await.expect("request")
    }

    /// `POST /api/models/{id}/versions`: a new version of a model.
    pub async fn upload_version(&self, model_id: &str, bundle: Vec<u8>, file_name: &str, fields: &[(&str, &str)]) -> Response {
        self.post_version_form(model_id, upload_form(bundle, file_name, fields)).await
    }

    /// Uploads a new model, expects 202 and returns `(model_id, version, job_id)`.
    pub async fn upload_model_ok(&self, bundle: Vec<u8>, fields: &[(&str, &str)]) -> (String, i64, String) {
        accepted(self.upload_model(bundle, "bundle.zip", fields).await).await
    }

    /// Uploads a new version, expects 202 and returns `(model_id, version, job_id)`.
    pub async fn upload_version_ok(&self, model_id: &str, bundle: Vec<u8>, fields: &[(&str, &str)]) -> (String, i64, String) {
        accepted(self.upload_version(model_id, bundle, "bundle.zip", fields).await).await
    }

    /// `GET /api/jobs/{id}`.
    pub async fn job(&self, job_id: &str) -> Response {
        self.get(&format!("/api/jobs/{job_id}")).await
    }

    /// Polls a job until it is `succeeded` or `failed` (30 s at most) and returns it.
    pub async fn wait_for_job(&self, job_id: &str) -> Value {
        self.wait_for_job_within(job_id, Duration::from_secs(30)).await
    }

    /// [`TestApp::wait_for_job`] with another time limit.
    pub async fn wait_for_job_within(&self, job_id: &str, within: Duration) -> Value {
        let deadline = std::time::Instant::now() + within;
        loop {
            let r = self.job(job_id).await;
            assert_eq!(r.status(), 200, "job {job_id}");
            let job: Value = r.json().await.expect("json");
            if job["status"] == "succeeded" || job["status"] == "failed" {
                return job;
            }
            assert!(std::time::Instant::now() < deadline, "job {job_id} still {} after {within:?}", job["status"]);
            tokio::time::sleep(Duration::from_millis(25)).await;
        }
    }

    /// `GET /api/models`.
    pub async fn models(&self) -> Response {
        self.get("/api/models").await
    }

    /// `GET /api/models/{id}`.
    pub async fn model(&self, model_id: &str) -> Response {
        self.get(&format!("/api/models/{model_id}")).await
    }

    /// `DELETE /api/models/{id}`.
    pub async fn delete_model(&self, model_id: &str) -> Response {
        self.client.delete(self.url(&format!("/api/models/{model_id}"))).send().await.expect("request")
    }

    /// `GET /api/models/{id}/versions`.
    pub async fn versions(&self, model_id: &str) -> Response {
        self.get(&format!("/api/models/{model_id}/versions")).await
    }

    /// `GET /api/models/{id}/versions/{v}` (`v` as text, so tests can send nonsense).
    pub async fn version(&self, model_id: &str, version: impl std::fmt::Display) -> Response {
        self.get(&format!("/api/models/{model_id}/versions/{version}")).await
    }

    /// `DELETE /api/models/{id}/versions/{v}`.
    pub async fn delete_version(&self, model_id: &str, version: i64) -> Response {
        self.client.delete(self.url(&format!("/api/models/{model_id}/versions/{version}"))).send().await.expect("request")
    }

    /// `GET /api/models/{id}/versions/{v}/package.zip`.
    pub async fn package(&self, model_id: &str, version: i64) -> Response {
        self.get(&format!("/api/models/{model_id}/versions/{version}/package.zip")).await
    }

    /// `GET /api/models/{id}/versions/{v}/report`.
    pub async fn report(&self, model_id: &str, version: i64) -> Response {
        self.get(&format!("/api/models/{model_id}/versions/{version}/report")).await
    }

    /// `GET /api/models/{id}/versions/{v}/bundle`.
    pub async fn bundle(&self, model_id: &str, version: i64) -> Response {
        self.get(&format!("/api/models/{model_id}/versions/{version}/bundle")).await
    }

    /// `GET /api/models/{id}/diff?from=..&to=..`.
    pub async fn diff(&self, model_id: &str, from: i64, to: i64) -> Response {
        self.get(&format!("/api/models/{model_id}/diff?from={from}&to={to}")).await
    }
}

/// Reads a 202 upload answer: `(model_id, version, job_id)`.
pub async fn accepted(r: Response) -> (String, i64, String) {
    let status = r.status();
    let body: Value = r.json().await.expect("json");
    assert_eq!(status, 202, "upload refused: {body:#}");
    let model_id = body["model_id"].as_str().expect("model_id").to_string();
    let version = body["version"].as_i64().expect("version");
    let job_id = body["job_id"].as_str().expect("job_id").to_string();
    (model_id, version, job_id)
}

/// Checks that `r` is a problem document with `status` (content type and `type` included) and
/// returns it.
pub async fn problem(r: Response, status: u16) -> Value {
    let got = r.status().as_u16();
    let ct = r.headers().get("content-type").and_then(|v| v.to_str().ok()).unwrap_or_default().to_string();
    let text = r.text().await.expect("body");
    assert_eq!(got, status, "expected {status}, got {got}: {text}");
    assert_eq!(ct, "application/problem+json", "content type of {text}");
    let p: Value = serde_json::from_str(&text).expect("problem is JSON");
    assert!(p["type"].as_str().is_some_and(|t| t.starts_with("/problems/")), "no type in {p}");
    assert_eq!(p["status"], status, "status in {p}");
    p
}
