#pragma once
// A real browser for tests: headless Chromium driven through the Chrome DevTools Protocol over
// --remote-debugging-pipe (commands on its fd 3, replies and events on its fd 4, each a JSON message
// ending in NUL), so no WebSocket client, driver or download is needed. Each page opens in a new tab; the
// session records every console error, uncaught exception, error log entry and requested URL of its tabs.
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace affinterp::checks {

class ChromiumSession {
 public:
  /// Chromium on PATH (Debian's `chromium`), if any.
  static std::optional<std::filesystem::path> find() {
    for (const char* name : {"chromium", "chromium-browser"}) {
      const char* path = std::getenv("PATH");
      std::string folders = path ? path : "";
      for (std::size_t at = 0; at <= folders.size();) {
        const std::size_t end = std::min(folders.find(':', at), folders.size());
        const std::filesystem::path candidate = std::filesystem::path(folders.substr(at, end - at)) / name;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
        at = end + 1;
      }
    }
    return std::nullopt;
  }

  /// Starts headless Chromium with a fresh profile in `profile` (the flags a root user on a machine
  /// without network needs: no sandbox, no background connections).
  ChromiumSession(const std::filesystem::path& chromium, const std::filesystem::path& profile) {
    int commands[2], replies[2];
    if (pipe(commands) != 0 || pipe(replies) != 0) throw std::runtime_error("pipe failed");
    pid_ = fork();
    if (pid_ == 0) {
      dup2(commands[0], 3);
      dup2(replies[1], 4);
      for (int fd : {commands[0], commands[1], replies[0], replies[1]})
        if (fd > 4) close(fd);
      const int null = ::open("/dev/null", O_WRONLY);
      dup2(null, 1), dup2(null, 2);
      const std::string user_data = "--user-data-dir=" + profile.string();
      execl(chromium.c_str(), chromium.c_str(), "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic",
            "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync",
            "--disable-extensions", "--remote-debugging-pipe", "--window-size=1200,900", user_data.c_str(),
            "about:blank", static_cast<char*>(nullptr));
      _exit(127);
    }
    close(commands[0]), close(replies[1]);
    to_browser_ = commands[1], from_browser_ = replies[0];
  }

  ~ChromiumSession() {
    try {
      send("Browser.close", {}, "");
    } catch (const std::exception&) {
    }
    close(to_browser_), close(from_browser_);
    for (int waited = 0; waited < 100 && waitpid(pid_, nullptr, WNOHANG) == 0; ++waited) usleep(50000);
    if (waitpid(pid_, nullptr, WNOHANG) == 0) kill(pid_, SIGKILL), waitpid(pid_, nullptr, 0);
  }
  ChromiumSession(const ChromiumSession&) = delete;
  ChromiumSession& operator=(const ChromiumSession&) = delete;

  /// Opens `url` in a new tab, which comes to the front, and waits for its load event.
  void open(const std::string& url) {
    const auto target = send("Target.createTarget", {{"url", "about:blank"}}, "");
    session_ = send("Target.attachToTarget", {{"targetId", target["targetId"]}, {"flatten", true}}, "")["sessionId"];
    for (const char* domain : {"Runtime.enable", "Log.enable", "Network.enable", "Page.enable"}) send(domain, {});
    send("Page.bringToFront", {});  // the visible tab: animation frames run as for a user
    loaded_ = false;
    send("Page.navigate", {{"url", url}});
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!loaded_) pump(deadline);
  }

  /// The value of a JavaScript expression in the current tab (promises awaited); throws on an exception.
  nlohmann::json evaluate(const std::string& expression) {
    const auto reply =
        send("Runtime.evaluate", {{"expression", expression}, {"returnByValue", true}, {"awaitPromise", true}});
    if (reply.contains("exceptionDetails")) throw std::runtime_error("evaluate: " + reply["exceptionDetails"].dump());
    return reply["result"].value("value", nlohmann::json());
  }

  /// A key pressed and released, as from the keyboard (e.g. "ArrowRight", 39).
  void press(const std::string& key, int key_code) {
    for (const char* type : {"rawKeyDown", "keyUp"})
      send("Input.dispatchKeyEvent", {{"type", type},
                                      {"key", key},
                                      {"code", key},
                                      {"windowsVirtualKeyCode", key_code},
                                      {"nativeVirtualKeyCode", key_code}});
  }

  /// A left click at the centre of the element `selector`, as from the mouse.
  void click(const std::string& selector) {
    const auto box = evaluate("(() => { const r = document.querySelector(" + nlohmann::json(selector).dump() +
                              ").getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2]; })()");
    for (const char* type : {"mousePressed", "mouseReleased"})
      send("Input.dispatchMouseEvent",
           {{"type", type}, {"x", box[0]}, {"y", box[1]}, {"button", "left"}, {"clickCount", 1}});
  }

  /// Lets the page run for `ms` milliseconds, collecting its events.
  void wait(int ms) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
    while (pump(deadline, false)) {
    }
  }

  /// Console errors, uncaught exceptions and error log entries of the tabs opened.
  const std::vector<std::string>& errors() const { return errors_; }
  /// Console warnings and other log entries of the tabs opened.
  const std::vector<std::string>& warnings() const { return warnings_; }
  /// The URLs the tabs requested.
  const std::vector<std::string>& requests() const { return requests_; }

 private:
  nlohmann::json send(const std::string& method, nlohmann::json params, std::optional<std::string> session = {}) {
    const int id = ++last_id_;
    nlohmann::json message = {
        {"id", id}, {"method", method}, {"params", params.is_null() ? nlohmann::json::object() : params}};
    const std::string target = session ? *session : session_;
    if (!target.empty()) message["sessionId"] = target;
    const std::string text = message.dump() + '\0';
    for (std::size_t written = 0; written < text.size();) {
      const ssize_t n = write(to_browser_, text.data() + written, text.size() - written);
      if (n <= 0) throw std::runtime_error("Chromium closed its pipe");
      written += static_cast<std::size_t>(n);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    for (;;) {
      if (auto reply = pump(deadline); reply && reply->value("id", 0) == id) {
        if (reply->contains("error")) throw std::runtime_error(method + ": " + (*reply)["error"].dump());
        return (*reply)["result"];
      }
    }
  }

  /// Reads one message (waiting until `deadline`), records it if it is an event, and returns it; with
  /// `must`, a deadline passed is an error, else it returns nothing.
  std::optional<nlohmann::json> pump(std::chrono::steady_clock::time_point deadline, bool must = true) {
    for (;;) {
      if (const auto end = buffer_.find('\0'); end != std::string::npos) {
        auto message = nlohmann::json::parse(buffer_.substr(0, end));
        buffer_.erase(0, end + 1);
        record(message);
        return message;
      }
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) {
        if (must) throw std::runtime_error("Chromium did not answer in time");
        return std::nullopt;
      }
      pollfd fd{from_browser_, POLLIN, 0};
      if (poll(&fd, 1, static_cast<int>(left.count())) <= 0) continue;
      char chunk[65536];
      const ssize_t n = read(from_browser_, chunk, sizeof chunk);
      if (n <= 0) throw std::runtime_error("Chromium closed its pipe");
      buffer_.append(chunk, static_cast<std::size_t>(n));
    }
  }

  void record(const nlohmann::json& message) {
    if (message.value("sessionId", "") != session_ || !message.contains("method")) return;
    const std::string method = message["method"];
    const auto& params = message["params"];
    if (method == "Page.loadEventFired") loaded_ = true;
    if (method == "Runtime.exceptionThrown") errors_.push_back("exception: " + params["exceptionDetails"].dump());
    if (method == "Runtime.consoleAPICalled" && (params["type"] == "error" || params["type"] == "assert"))
      errors_.push_back("console." + params["type"].get<std::string>() + ": " + params["args"].dump());
    if (method == "Runtime.consoleAPICalled" && params["type"] == "warning")
      warnings_.push_back("console.warning: " + params["args"].dump());
    if (method == "Log.entryAdded")
      (params["entry"]["level"] == "error" ? errors_ : warnings_)
          .push_back("log: " + params["entry"].value("text", ""));
    if (method == "Network.requestWillBeSent") requests_.push_back(params["request"]["url"]);
  }

  pid_t pid_ = -1;
  int to_browser_ = -1, from_browser_ = -1, last_id_ = 0;
  std::string session_, buffer_;
  bool loaded_ = false;
  std::vector<std::string> errors_, warnings_, requests_;
};

}  // namespace affinterp::checks
