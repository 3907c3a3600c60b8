{{ 'hELLo wORLD' | lower }} {{ 'hello' | upper }} {{ 'hello WORLD' | capitalize }} {{ 'hello big-world (x)y [z' | title }}
{{ 'ßtraße' | upper }} {{ 'ΣΑΣ ΑΣ' | lower }} {{ 'İ' | lower | length }} {{ 'ǆx' | capitalize }} {{ 'éCOLE' | title }}
{{ 42 | lower }} {{ none | upper }} {{ lower }}|{{ undefinedvalue | upper }}|
