//! `TestApp` methods for the motor library endpoints, one per route (plus a raw POST for bodies
//! that are not JSON).

use crate::app::TestApp;

impl TestApp {
    async fn send_json(&self, method: reqwest::Method, path: &str, body: &serde_json::Value) -> reqwest::Response {
        self.client.request(method, self.url(path)).json(body).send().await.expect("request")
    }

    async fn send_delete(&self, path: &str) -> reqwest::Response {
        self.client.delete(self.url(path)).send().await.expect("request")
    }

    /// `GET /api/library/classes`
    pub async fn library_classes(&self) -> reqwest::Response {
        self.get("/api/library/classes").await
    }

    /// `GET /api/library/classes/{id}`
    pub async fn library_class(&self, id: &str) -> reqwest::Response {
        self.get(&format!("/api/library/classes/{id}")).await
    }

    /// `POST /api/library/classes`
    pub async fn create_library_class(&self, body: &serde_json::Value) -> reqwest::Response {
        self.send_json(reqwest::Method::POST, "/api/library/classes", body).await
    }

    /// `PUT /api/library/classes/{id}`
    pub async fn update_library_class(&self, id: &str, body: &serde_json::Value) -> reqwest::Response {
        self.send_json(reqwest::Method::PUT, &format!("/api/library/classes/{id}"), body).await
    }

    /// `DELETE /api/library/classes/{id}`
    pub async fn delete_library_class(&self, id: &str) -> reqwest::Response {
        self.send_delete(&format!("/api/library/classes/{id}")).await
    }

    /// `GET /api/library/instances` with a query string (`""`, `"?domain=motor"`, ...).
    pub async fn library_instances(&self, query: &str) -> reqwest::Response {
        self.get(&format!("/api/library/instances{query}")).await
    }

    /// `GET /api/library/instances/{id}`
    pub async fn library_instance(&self, id: &str) -> reqwest::Response {
        self.get(&format!("/api/library/instances/{id}")).await
    }

    /// `POST /api/library/instances`
    pub async fn create_library_instance(&self, body: &serde_json::Value) -> reqwest::Response {
        self.send_json(reqwest::Method::POST, "/api/library/instances", body).await
    }

    /// `PUT /api/library/instances/{id}`
    pub async fn update_library_instance(&self, id: &str, body: &serde_json::Value) -> reqwest::Response {
        self.send_json(reqwest::Method::PUT, &format!("/api/library/instances/{id}"), body).await
    }

    /// `DELETE /api/library/instances/{id}`
    pub async fn delete_library_instance(&self, id: &str) -> reqwest::Response {
        self.send_delete(&format!("/api/library/instances/{id}")).await
    }

    /// `GET /api/library/export`
    pub async fn export_library(&self) -> reqwest::Response {
        self.get("/api/library/export").await
    }

    /// `POST /api/library/import` with an XML body.
    pub async fn import_library(&self, xml: impl Into<reqwest::Body>) -> reqwest::Response {
        self.client.post(self.url("/api/library/import")).header("content-type", "application/xml").body(xml).send().await.expect("request")
    }

    /// A request with any method, content type and raw body (malformed JSON and the like).
    pub async fn library_raw(&self, method: reqwest::Method, path: &str, content_type: &str, body: &'static str) -> reqwest::Response {
        self.client.request(method, self.url(path)).header("content-type", content_type).body(body).send().await.expect("request")
    }
}
