#include "shader_preprocessor.h"

#include <cctype>
#include <set>
#include <sstream>

namespace caustics::test {
namespace {

std::string stripComments(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s.compare(i, 2, "//") == 0) {
            while (i < s.size() && s[i] != '\n') ++i;
            if (i < s.size()) out += '\n';
        } else if (s.compare(i, 2, "/*") == 0) {
            size_t end = s.find("*/", i + 2);
            for (size_t j = i; j < std::min(end, s.size()); ++j)
                if (s[j] == '\n') out += '\n';   // keep line structure
            i = end == std::string::npos ? s.size() : end + 1;
        } else {
            out += s[i];
        }
    }
    return out;
}

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string trim(const std::string& s) {
    size_t b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

class Preprocessor {
public:
    Preprocessor(std::map<std::string, std::string> macros, std::vector<std::string> dirs, IncludeReader read)
        : macros_(std::move(macros)), dirs_(std::move(dirs)), read_(std::move(read)) {}

    void run(const std::string& source, const std::string& fileDir, int depth) {
        std::istringstream in(stripComments(source));
        struct Cond { bool parentActive, anyTaken, active; };
        std::vector<Cond> stack;
        auto active = [&] { return stack.empty() || stack.back().active; };
        std::string line;
        while (std::getline(in, line)) {
            std::string t = trim(line);
            if (t.empty() || t[0] != '#') {
                if (active()) out.text += expand(line) + "\n";
                continue;
            }
            std::string body = trim(t.substr(1));
            size_t sp = body.find_first_of(" \t(");
            std::string directive = body.substr(0, sp), rest = sp == std::string::npos ? "" : trim(body.substr(sp));
            if (directive == "ifdef" || directive == "ifndef") {
                bool value = macros_.count(rest) == (directive == "ifdef" ? 1u : 0u);
                stack.push_back({active(), value, active() && value});
            } else if (directive == "if") {
                bool value = evaluate(rest);
                stack.push_back({active(), value, active() && value});
            } else if (directive == "elif" || directive == "else") {
                if (stack.empty()) { out.problems.push_back("#" + directive + " without #if"); continue; }
                Cond& c = stack.back();
                bool value = !c.anyTaken && (directive == "else" || evaluate(rest));
                c.active = c.parentActive && value;
                c.anyTaken = c.anyTaken || value;
            } else if (directive == "endif") {
                if (!stack.empty()) stack.pop_back();
            } else if (!active()) {
                continue;
            } else if (directive == "define") {
                define(rest);
            } else if (directive == "undef") {
                macros_.erase(rest);
            } else if (directive == "include") {
                include(rest, fileDir, depth);
            }   // #version, #extension, #pragma: nothing an interface depends on
        }
    }

    PreprocessedShader out;

private:
    void define(const std::string& rest) {
        size_t n = 0;
        while (n < rest.size() && isIdentChar(rest[n])) ++n;
        std::string name = rest.substr(0, n);
        if (n < rest.size() && rest[n] == '(') macros_[name] = "";   // function-like: defined, not expanded
        else macros_[name] = trim(rest.substr(n));
    }

    void include(const std::string& rest, const std::string& fileDir, int depth) {
        size_t a = rest.find('"'), b = rest.rfind('"');
        if (a == std::string::npos || b <= a || !read_) { out.problems.push_back("unreadable #include " + rest); return; }
        std::string target = rest.substr(a + 1, b - a - 1);
        if (depth > 32) { out.problems.push_back("#include nesting too deep at " + target); return; }
        std::vector<std::string> dirs = {fileDir};
        dirs.insert(dirs.end(), dirs_.begin(), dirs_.end());
        for (const std::string& dir : dirs) {
            std::string path = dir + "/" + target;
            if (auto text = read_(path)) {
                run(*text, path.substr(0, path.rfind('/')), depth + 1);
                return;
            }
        }
        out.problems.push_back("#include \"" + target + "\" not found");
    }

    std::string expand(const std::string& line, int depth = 0) const {
        std::string result;
        bool changed = false;
        for (size_t i = 0; i < line.size();) {
            if (isIdentStart(line[i]) && (i == 0 || !isIdentChar(line[i - 1]))) {
                size_t j = i;
                while (j < line.size() && isIdentChar(line[j])) ++j;
                std::string word = line.substr(i, j - i);
                auto it = macros_.find(word);
                if (it != macros_.end() && !it->second.empty()) { result += it->second; changed = true; }
                else result += word;
                i = j;
            } else {
                result += line[i++];
            }
        }
        return changed && depth < 8 ? expand(result, depth + 1) : result;
    }

    // #if expressions: defined(X) / defined X, !, &&, ||, parentheses, integer literals and macros.
    bool evaluate(const std::string& expr) {
        pos_ = 0;
        expr_ = expr;
        bool ok = true;
        long v = orExpr(ok);
        if (!ok) out.problems.push_back("unreadable #if " + expr);
        return ok && v != 0;
    }
    void skipSpace() { while (pos_ < expr_.size() && std::isspace(static_cast<unsigned char>(expr_[pos_]))) ++pos_; }
    bool eat(const char* token) {
        skipSpace();
        if (expr_.compare(pos_, std::char_traits<char>::length(token), token) != 0) return false;
        pos_ += std::char_traits<char>::length(token);
        return true;
    }
    long orExpr(bool& ok) {
        long v = andExpr(ok);
        while (eat("||")) v = (andExpr(ok) != 0) || v;
        return v;
    }
    long andExpr(bool& ok) {
        long v = unary(ok);
        while (eat("&&")) v = (unary(ok) != 0) && v;
        return v;
    }
    long unary(bool& ok) {
        if (eat("!")) return !unary(ok);
        if (eat("(")) { long v = orExpr(ok); if (!eat(")")) ok = false; return v; }
        skipSpace();
        size_t start = pos_;
        while (pos_ < expr_.size() && isIdentChar(expr_[pos_])) ++pos_;
        std::string word = expr_.substr(start, pos_ - start);
        if (word.empty()) { ok = false; return 0; }
        if (word == "defined") {
            bool paren = eat("(");
            skipSpace();
            size_t s = pos_;
            while (pos_ < expr_.size() && isIdentChar(expr_[pos_])) ++pos_;
            long v = macros_.count(expr_.substr(s, pos_ - s)) ? 1 : 0;
            if (paren && !eat(")")) ok = false;
            return v;
        }
        if (std::isdigit(static_cast<unsigned char>(word[0]))) return std::stol(word);
        auto it = macros_.find(word);
        if (it != macros_.end() && !it->second.empty() && std::isdigit(static_cast<unsigned char>(it->second[0])))
            return std::stol(it->second);
        return 0;   // an undefined identifier is 0, as in C
    }

    std::map<std::string, std::string> macros_;
    std::vector<std::string> dirs_;
    IncludeReader read_;
    std::string expr_;
    size_t pos_ = 0;
};

}  // namespace

PreprocessedShader preprocessShader(const std::string& source, const std::map<std::string, std::string>& predefined,
                                    const std::vector<std::string>& includeDirs, const IncludeReader& read) {
    Preprocessor p(predefined, includeDirs, read);
    p.run(source, includeDirs.empty() ? "." : includeDirs.front(), 0);
    return std::move(p.out);
}

}  // namespace caustics::test
