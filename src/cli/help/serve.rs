//! The help of `phong serve` (`super::super::args::serve`).

use super::{Part, Texts};

crate::messages! {
    /// The help of `phong serve` and of its arguments.
    pub(crate) enum ServeHelp {
        /// `phong serve`.
        Serve =>
            "Serve the exercises as a web application: a student checks an answer (and its \
             steps) in a browser, Portuguese or English, with nothing installed; a JSON API \
             mirrors `solve --format json` and `check --format json`",
            "Serve os exercícios como uma aplicação web: o aluno confere uma resposta (e os seus \
             passos) no navegador, em português ou inglês, sem instalar nada; uma API JSON \
             espelha `solve --format json` e `check --format json`";
        /// `serve --addr`.
        Addr =>
            "The address to listen on; port 0 picks a free port (printed at start-up). Behind a \
             reverse proxy, keep the loopback address",
            "O endereço em que escutar; a porta 0 escolhe uma porta livre (mostrada na \
             partida). Atrás de um proxy reverso, mantenha o endereço de loopback";
        /// `serve --exercises`.
        Exercises =>
            "Serve every *.json problem of this folder (each checked at start-up) instead of the \
             bundled exercises",
            "Serve cada problema *.json desta pasta (cada um verificado na partida) em vez dos \
             exercícios embutidos";
        /// `serve --policy`.
        Policy =>
            "The course policy answers are judged by [default: course-policy.json in \
             --exercises, else the defaults]",
            "A política do curso pela qual as respostas são julgadas [padrão: \
             course-policy.json em --exercises, senão os padrões]";
        /// `serve --log-answers`.
        LogAnswers =>
            "Append each checked answer to this file, one JSON line each (the answer's first 64 \
             characters, its length and its hash); without it, no answer is kept",
            "Acrescenta cada resposta conferida a este arquivo, uma linha JSON cada (os \
             primeiros 64 caracteres da resposta, o seu tamanho e o seu hash); sem esta opção, \
             nenhuma resposta é guardada";
        /// `serve --log-answers-max`.
        LogAnswersMax =>
            "The most kB (1,000 bytes) the answers' log holds: before a line would pass it, \
             PATH is renamed PATH.1 (replacing the older one) and a new PATH begun, so the two \
             hold at most twice this",
            "O máximo de kB (1.000 bytes) que o registro das respostas guarda: antes que uma \
             linha o ultrapasse, PATH é renomeado para PATH.1 (substituindo o mais antigo) e um \
             novo PATH é começado, então os dois guardam no máximo o dobro disso";
        /// `serve --max-concurrent`.
        MaxConcurrent =>
            "The most requests handled at once; more are refused with 503 at once",
            "O máximo de requisições atendidas ao mesmo tempo; as demais são recusadas na hora \
             com 503";
        /// `serve --max-connections`.
        MaxConnections =>
            "The most connections open at once (idle keep-alive ones included); more are closed \
             as soon as they are accepted",
            "O máximo de conexões abertas ao mesmo tempo (incluídas as keep-alive ociosas); as \
             demais são fechadas assim que aceitas";
        /// `serve --max-connections-per-client`.
        MaxConnectionsPerClient =>
            "The most connections open at once from one client address (an IPv6 client's /64); \
             more are closed as soon as they are accepted. Behind a reverse proxy every client \
             is the proxy: give it --max-connections, and limit clients in the proxy",
            "O máximo de conexões abertas ao mesmo tempo de um endereço de cliente (o /64 de um \
             cliente IPv6); as demais são fechadas assim que aceitas. Atrás de um proxy \
             reverso, todo cliente é o proxy: dê a ele --max-connections e limite os clientes no \
             proxy";
        /// `serve --timeout`.
        Timeout =>
            "The most seconds a request may take (its body's arrival included)",
            "O máximo de segundos que uma requisição pode levar (incluída a chegada do corpo)";
        /// `serve --header-timeout`.
        HeaderTimeout =>
            "The most seconds a client may take to send a request's headers, or leave a \
             connection idle between requests (at most --timeout)",
            "O máximo de segundos que um cliente pode levar para enviar os cabeçalhos de uma \
             requisição, ou deixar uma conexão ociosa entre requisições (no máximo --timeout)";
    }
}

/// The help of `part` of `command`, for `phong serve`.
pub(super) fn of(command: &str, part: Part<'_>) -> Option<Texts> {
    use Part::{About, Arg};
    use ServeHelp as H;
    if command != "serve" {
        return None;
    }
    Some(Texts::new(match part {
        About => H::Serve,
        Arg("addr") => H::Addr,
        Arg("exercises") => H::Exercises,
        Arg("policy") => H::Policy,
        Arg("log_answers") => H::LogAnswers,
        Arg("log_answers_max") => H::LogAnswersMax,
        Arg("max_concurrent") => H::MaxConcurrent,
        Arg("max_connections") => H::MaxConnections,
        Arg("max_connections_per_client") => H::MaxConnectionsPerClient,
        Arg("timeout") => H::Timeout,
        Arg("header_timeout") => H::HeaderTimeout,
        Arg(_) => return None,
    }))
}
