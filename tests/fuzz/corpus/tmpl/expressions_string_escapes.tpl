{{ 'tab\there' }}|{{ "quote\"s" }}|{{ 'it\'s' }}|{{ 'back\\slash' }}|{{ 'nl\nx' }}
{{ '\x41\u00e9\U0001F600\101' }}|{{ 'unknown \d escape' }}|{{ ['\t', '\\', "\x00"] }}
